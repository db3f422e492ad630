//! The Sierpiński cube: a cube split into 27 subcubes, of which the centre
//! ([`CubeVariant::Centre`], 26 kept, dimension log 26/log 3 ≈ 2.97) or the centre and the
//! six face centres ([`CubeVariant::Axes`], 20 kept: the Menger sponge, ≈ 2.73) are
//! removed, recursively; projected orthographically from a [`Camera`] and painted with
//! flat shading per face direction.
//!
//! No list of cubes is kept: the kept cubes of the last level are visited depth first with
//! an explicit stack of child indices, in an order that is back to front for the camera
//! (each axis from the side away from the viewer: a cube can hide another only if it is
//! at least as near on every axis, so this order paints the hidden one first). Of each
//! cube only the faces turned to the camera are considered, and of those only the ones
//! that can be seen: a face against a kept neighbour is never drawn, nor (in the centre
//! variant, whose holes are closed on every side) a face onto a hole. In the axes variant
//! a face onto a tunnel is drawn and may be painted over by nearer cubes.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::order::{check_order, depth_first, power};
use crate::error::{Error, FitError, ParameterError};
use crate::math::affine::Affine3;
use crate::math::divide::div_rem_by_3;
use crate::math::trig::ONE_Q30;
use crate::math::Real;
use crate::render::polygon::{fill_convex, SubPixel, SUBPIXEL_BITS};

/// Which subcubes a step removes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CubeVariant {
    /// Only the central subcube: 26 kept.
    Centre,
    /// The centre and the six face centres (the subcubes on the central axes): 20 kept,
    /// the Menger sponge.
    Axes,
}

impl CubeVariant {
    /// Subcubes kept per step.
    pub const fn kept(self) -> u64 {
        match self {
            Self::Centre => 26,
            Self::Axes => 20,
        }
    }

    /// Whether the subcube at digits (x, y, z), each 0..3, is kept.
    const fn keeps(self, x: u32, y: u32, z: u32) -> bool {
        let ones = (x == 1) as u32 + (y == 1) as u32 + (z == 1) as u32;
        match self {
            Self::Centre => ones < 3,
            Self::Axes => ones < 2,
        }
    }
}

/// Where the camera looks from: degrees around the vertical axis (from +x towards +y) and
/// above the horizontal plane. Projection is orthographic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Camera {
    /// Degrees around the vertical axis.
    pub azimuth: Real,
    /// Degrees above the horizontal plane, strictly between −90 and 90.
    pub elevation: Real,
}

impl Camera {
    /// The isometric view: azimuth 45°, elevation 35.264° (atan(1/√2)).
    pub const ISOMETRIC: Self = Self {
        azimuth: Real::from_int(45),
        elevation: match Real::from_ratio(35_264, 1000) {
            Some(value) => value,
            None => Real::ZERO,
        },
    };
}

impl Default for Camera {
    fn default() -> Self {
        Self::ISOMETRIC
    }
}

/// The Sierpiński cube at an order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SierpinskiCube {
    /// Levels of subdivision (0: one cube).
    pub order: u32,
    /// Which subcubes a step removes.
    pub variant: CubeVariant,
    /// Where it is seen from.
    pub camera: Camera,
}

/// What drawing a cube did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CubeStats {
    /// Kept cubes of the last level visited: 26ᴺ or 20ᴺ.
    pub cubes: u64,
    /// Faces painted.
    pub faces: u64,
}

impl SierpinskiCube {
    /// The cube at `order` with `variant`, seen isometrically.
    pub const fn new(order: u32, variant: CubeVariant) -> Self {
        Self {
            order,
            variant,
            camera: Camera::ISOMETRIC,
        }
    }

    /// The same cube seen from `camera`.
    #[must_use]
    pub const fn with_camera(mut self, camera: Camera) -> Self {
        self.camera = camera;
        self
    }

    /// Kept cubes at this order: 26ᴺ or 20ᴺ.
    pub const fn cubes(&self) -> u64 {
        power(self.variant.kept(), self.order)
    }

    /// The cube as large as fits `area`, centred, its faces `color` shaded by their
    /// direction, on `background`. Fails when a cube of the last level would be under a
    /// pixel across, or the camera looks straight up or down.
    pub fn fit<C>(
        &self,
        area: Rectangle,
        color: Rgb888,
        background: C,
    ) -> Result<CubeDrawing<C>, Error>
    where
        C: PixelColor + From<Rgb888>,
    {
        let camera_error = Error::Parameter(ParameterError::CameraOutOfRange {
            azimuth: self.camera.azimuth,
            elevation: self.camera.elevation,
        });
        let ninety = Real::from_int(90);
        if self.camera.elevation >= ninety
            || self.camera.elevation <= Real::ZERO.saturating_sub(ninety)
        {
            return Err(camera_error);
        }
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        // Screen right, screen up and towards the viewer, per world axis (Q30).
        let view = Affine3::camera(self.camera.azimuth, self.camera.elevation);
        let [right, up, toward] = view
            .matrix
            .map(|row| row.map(|v| (v.to_bits() >> 2) as i32));
        let spread = |v: &[i32; 3]| v.iter().map(|c| i64::from(c.unsigned_abs())).sum::<i64>();
        let (w, h) = (i64::from(area.size.width), i64::from(area.size.height));
        // Pixels per unit of the whole cube's side, the tighter of width and height, Q16.
        let (across, tall) = (spread(&right).max(1), spread(&up).max(1));
        let unit_q16 =
            ((w << (30 + SUBPIXEL_BITS)) / across).min((h << (30 + SUBPIXEL_BITS)) / tall);
        check_order(self.order, 3, (unit_q16 >> SUBPIXEL_BITS) as u64)?;
        let side = power(3, self.order) as i64;
        let cell_q16 = unit_q16 / side;
        let steps: [SubPixel; 3] = core::array::from_fn(|i| {
            let r = right.get(i).copied().unwrap_or(0);
            let u = up.get(i).copied().unwrap_or(0);
            (
                (i64::from(r) * cell_q16) >> 30,
                -((i64::from(u) * cell_q16) >> 30),
            )
        });
        // Centre the projected box of the 8 corners in the area.
        let (mut low, mut high) = ((0i64, 0i64), (0i64, 0i64));
        for &(dx, dy) in &steps {
            let (ex, ey) = (dx * side, dy * side);
            low = (low.0 + ex.min(0), low.1 + ey.min(0));
            high = (high.0 + ex.max(0), high.1 + ey.max(0));
        }
        let centre = (
            (i64::from(area.top_left.x) << SUBPIXEL_BITS) + (w << SUBPIXEL_BITS) / 2,
            (i64::from(area.top_left.y) << SUBPIXEL_BITS) + (h << SUBPIXEL_BITS) / 2,
        );
        let origin = (
            centre.0 - (low.0 + high.0) / 2,
            centre.1 - (low.1 + high.1) / 2,
        );
        // Light from above, a little from the left and from the viewer; shade = 0.35 +
        // 0.65·(n·l) for the face normal n.
        let light: [i64; 3] = core::array::from_fn(|i| {
            let pick = |v: &[i32; 3]| i64::from(v.get(i).copied().unwrap_or(0));
            (3 * pick(&toward) + 8 * pick(&up) - 5 * pick(&right)) / 10
        });
        let mut faces = [None; 3];
        for (axis, face) in faces.iter_mut().enumerate() {
            let sign = toward.get(axis).copied().unwrap_or(0).signum();
            if sign == 0 {
                continue;
            }
            let lit = (i64::from(sign) * light.get(axis).copied().unwrap_or(0))
                .clamp(0, i64::from(ONE_Q30));
            let shade = 22_938 + ((lit * 42_598) >> 30); // 0.35 + 0.65·lit, Q16
            let scale = |c: u8| ((i64::from(c) * shade) >> 16).clamp(0, 255) as u8;
            *face = Some(Face {
                positive: sign > 0,
                color: C::from(Rgb888::new(
                    scale(color.r()),
                    scale(color.g()),
                    scale(color.b()),
                )),
            });
        }
        Ok(CubeDrawing {
            order: self.order,
            side,
            variant: self.variant,
            area,
            origin,
            steps,
            faces,
            background,
        })
    }
}

/// A cell visited (coordinates in cells of its level) and the sum of its coordinates times
/// the steps of a last-level cell: at the last level, where the cell's corner (0, 0, 0)
/// projects from the cube's (Q16 pixels).
type Placed = ([i64; 3], SubPixel);

/// The sum of two screen points.
fn add(a: SubPixel, b: SubPixel) -> SubPixel {
    (a.0 + b.0, a.1 + b.1)
}

/// A face direction turned to the camera: which side of its axis, and its shaded colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Face<C> {
    positive: bool,
    color: C,
}

/// A Sierpiński cube fitted to an area: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CubeDrawing<C> {
    order: u32,
    /// Cells along an edge: 3ᴺ.
    side: i64,
    variant: CubeVariant,
    area: Rectangle,
    /// Where the cube's corner (0, 0, 0) projects, Q16 pixels.
    origin: SubPixel,
    /// One cell along x, y and z on the screen, Q16 pixels.
    steps: [SubPixel; 3],
    /// The faces turned to the camera, per axis.
    faces: [Option<Face<C>>; 3],
    background: C,
}

impl<C: PixelColor> CubeDrawing<C> {
    /// Whether the cell at `cell` (coordinates of the last level) is kept, and `None` for
    /// a cell outside the cube.
    fn kept(&self, cell: [i64; 3]) -> Option<bool> {
        // A coordinate within the side (at most 3¹²) fits 32 bits, whose division by 3
        // needs no library call on ARMv6-M.
        let within = |c: i64| u32::try_from(c).ok().filter(|_| c < self.side);
        let [Some(mut x), Some(mut y), Some(mut z)] = cell.map(within) else {
            return None;
        };
        for _ in 0..self.order {
            let ((qx, rx), (qy, ry), (qz, rz)) =
                (div_rem_by_3(x), div_rem_by_3(y), div_rem_by_3(z));
            if !self.variant.keeps(rx, ry, rz) {
                return Some(false);
            }
            (x, y, z) = (qx, qy, qz);
        }
        Some(true)
    }

    /// Paints the visible faces of the kept cell `cell` of the last level, whose corner
    /// (0, 0, 0) projects `from_origin` from the cube's; returns how many.
    fn paint_cell<D>(
        &self,
        target: &mut D,
        (cell, from_origin): Placed,
        clip: &Rectangle,
    ) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut painted = 0;
        for (axis, face) in self.faces.iter().enumerate() {
            let Some(face) = face else { continue };
            let mut beyond = cell;
            let offset = if face.positive { 1 } else { -1 };
            if let Some(c) = beyond.get_mut(axis) {
                *c += offset;
            }
            let visible = match self.kept(beyond) {
                None => true,
                Some(true) => false,
                Some(false) => self.variant == CubeVariant::Axes,
            };
            if !visible {
                continue;
            }
            // The face's corners: the cell's corner on the face's side, then around it,
            // a cell's step along each of the other two axes.
            let step = |i: usize| self.steps.get(i % 3).copied().unwrap_or((0, 0));
            let mut corner = add(self.origin, from_origin);
            if face.positive {
                corner = add(corner, step(axis));
            }
            let (j, k) = (step(axis + 1), step(axis + 2));
            let quad = [
                corner,
                add(corner, j),
                add(add(corner, j), k),
                add(corner, k),
            ];
            fill_convex(target, &quad, face.color, clip)?;
            painted += 1;
        }
        Ok(painted)
    }
}

impl<C: PixelColor> Dimensions for CubeDrawing<C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> Drawable for CubeDrawing<C> {
    type Color = C;
    type Output = CubeStats;

    fn draw<D>(&self, target: &mut D) -> Result<CubeStats, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        target.fill_solid(&self.area, self.background)?;
        let clip = self.area.intersection(&target.bounding_box());
        let mut stats = CubeStats::default();
        // Each axis from the far side: ascending where the viewer is on the + side.
        let ascending: [bool; 3] = core::array::from_fn(|axis| {
            self.faces
                .get(axis)
                .copied()
                .flatten()
                .is_none_or(|face| face.positive)
        });
        let digit = |d: u32, axis: usize| {
            if ascending.get(axis).copied().unwrap_or(true) {
                d
            } else {
                2 - d
            }
        };
        if self.order == 0 {
            stats.cubes = 1;
            stats.faces = self.paint_cell(target, Placed::default(), &clip)?;
            return Ok(stats);
        }
        depth_first(
            self.order,
            27,
            |level, (parent, from_origin): Placed, child| {
                let c = u32::from(child);
                let digits = [digit(c / 9, 0), digit(c / 3 % 3, 1), digit(c % 3, 2)];
                let [dx, dy, dz] = digits;
                if !self.variant.keeps(dx, dy, dz) {
                    return Ok(None);
                }
                // A child's corner: three times its parent's (in cells of the next level) and
                // its digits', by additions alone (the same sums as each coordinate times its
                // step: no 64-bit products, which are library calls on ARMv6-M).
                let mut at = parent;
                let mut point = add(from_origin, add(from_origin, from_origin));
                for ((c, d), &(sx, sy)) in at.iter_mut().zip(digits).zip(&self.steps) {
                    *c = 3 * *c + i64::from(d);
                    for _ in 0..d {
                        point = add(point, (sx, sy));
                    }
                }
                let placed = (at, point);
                if level < self.order {
                    return Ok(Some(placed));
                }
                stats.cubes += 1;
                stats.faces += self.paint_cell(target, placed, &clip)?;
                Ok(None)
            },
        )?;
        Ok(stats)
    }
}
