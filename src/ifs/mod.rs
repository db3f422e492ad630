//! Iterated function systems by the chaos game (the Barnsley fern, Fractint's `.ifs`
//! files), and the gingerbread man: reader → maps → chaos game → drawing.

pub(crate) mod chaos;
pub(crate) mod file;
pub(crate) mod gingerbread;
pub(crate) mod maps;

pub use chaos::{
    ChaosGame, DensityDrawing, IfsDrawing, IfsPicture, IfsPoint, DENSITY_LEVELS, SKIPPED,
};
pub use file::{IfsEntry, IfsFile};
pub use gingerbread::{Cycle, Gingerbread, GingerbreadDrawing, GingerbreadPoints, MapPoint};
pub use maps::{AffineMap, Ifs, MAX_MAPS};
