//! What to compute: the fractal, the window onto the complex plane, the iteration cap, and
//! the fixed-point tier that has enough bits for that window and no more.

use embedded_graphics::geometry::Size;

use super::modes::{Inside, Outside};
use crate::error::{Error, FitError, ViewError};
use crate::math::wide::{div_round, mul_wide, shift_round};
use crate::math::{Coord, DeepCoord};

/// [`View::MAX_ITERATIONS`], for the crate's own types and arrays.
pub(crate) const MAX_ITERATIONS: u32 = u16::MAX as u32;

/// [`View::MAX_SMOOTH_ITERATIONS`], for the crate's own types and arrays.
pub(crate) const MAX_SMOOTH_ITERATIONS: u32 = (u16::MAX as u32) >> SMOOTH_FRACTION_BITS;

/// The inside value of the distance shading ([`Shading::Distance`]), whose values are 16
/// a doubling of the distance, 1 at 1/16 of a pixel, 65 at one pixel, up to 255.
pub const DISTANCE_INSIDE: u16 = 256;

/// Fractional bits of a smooth value: sixteenths of an iteration.
pub const SMOOTH_FRACTION_BITS: u32 = 4;

/// Largest |re| or |im| of any pixel of a view. Keeping points within 3.5 bounds every
/// orbit value below 8 before it escapes, so no tier can overflow.
const COORDINATE_LIMIT: i64 = 7 << 59; // 3.5 in Q60

/// The finest pixel spacing, 2⁻⁵⁴ in Q60 bits: the deep tier keeps 6 bits below it.
const FINEST_SPACING: i64 = 1 << 6;

/// The automatic tier of a Mandelbrot view is perturbation from this z + i on, where it is
/// not `Wide` (z and i as in [`View::new`]'s rule).
const PERTURBATION_FROM: u32 = 51;

/// A Mandelbrot view with z + i above this and a cap over 256 takes `Wide` while z is
/// below [`WIDE_BELOW`] (z and i as in [`View::new`]'s rule): `Deep` loses dwells there.
const DEEP_UNTIL: u32 = 25;

/// Below this z, only `Wide` keeps the long orbits `Deep` loses; from it, perturbation
/// does at caps up to 2048 (z + i ≥ [`PERTURBATION_FROM`]).
const WIDE_BELOW: u32 = 40;

/// From this i on (caps over 2048), a Mandelbrot view past z + i = [`DEEP_UNTIL`] takes
/// `Wide` at any z (perturbation loses dwells there too), and so does every Julia view
/// (`Deep` loses them).
const LONG_ORBIT: u32 = 12;

/// A Julia view with z + i above this takes `Wide`: `Deep` loses dwells there (and at caps
/// over 2048, see [`LONG_ORBIT`]).
const JULIA_DEEP_UNTIL: u32 = 22;

/// Perturbation's finest pixel spacing is 2 to the minus this.
const FINEST_PERTURBATION_BITS: u32 = 148;

/// Which escape-time fractal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fractal {
    /// z₀ = 0, z ← z² + c with c the pixel's point.
    Mandelbrot,
    /// z₀ = the pixel's point, z ← z² + k; |k| must be at most 2.
    Julia {
        /// The parameter k, real part.
        re: Coord,
        /// The parameter k, imaginary part.
        im: Coord,
    },
}

/// The fixed-point number format a render iterates in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Tier {
    /// Q12 in `i32` whose products fit 32 bits, for Cortex-M0/M0+ (no 32×32→64 multiply).
    /// Only chosen by hand: it is fast and coarse (98 % of dwells identical to an f64 model
    /// on the full Mandelbrot view at 320×240 or 128×64).
    Narrow,
    /// Q28 in `i32` whose products keep their high 32 bits (Q24): one `smull` and no shifts
    /// per product on cores with a long multiply, so about three quarters of `Standard`'s
    /// instructions per step, with 24 bits of precision. A Julia set's products are rounded
    /// (`smmulr` on Cortex-M4, the same count), which keeps as many dwells as a naive `f32`
    /// loop; the Mandelbrot views it is chosen for keep every dwell with products rounded
    /// down, an add a product fewer on Cortex-M3 and M0. Chosen for the Mandelbrot
    /// set while log₂(1/d) + log₂(max-iter) ≤ 12 (the full view at 128×64 and 64
    /// iterations), and for Julia sets at ⌈log₂(1/d)⌉ = 7 and 65–128 iterations (the whole
    /// set at 320×240 and 100 iterations; the calibrated rule: [`View::new`]).
    Medium,
    /// Q28 in `i32` with 64-bit products (Fractint used Q29; Q28 leaves room for |c| ≤ 3.5).
    /// Chosen for the Mandelbrot set while log₂(1/d) + log₂(max-iter) ≤ 15: the full view
    /// at 320×240 and 256 iterations, or views 4× deeper at 64 iterations; for Julia sets
    /// while log₂(1/d) + 7·log₂(max-iter) ≤ 56 where `Medium` is not chosen: 128×64 at 100
    /// iterations.
    Standard,
    /// Q60 in `i64` with 128-bit products, for zooms and long-running Julia sets.
    /// Deepest zoom: pixel spacing ≥ 2⁻⁵⁴ (a width of 1.8·10⁻¹⁴ on 320 pixels). Chosen for
    /// the Mandelbrot set while z + i ≤ 25, or at caps up to 256, or from z = 40 at caps up
    /// to 1024 while z + i ≤ 50 (see [`View::new`]): past that, its rounding loses dwells
    /// `Wide` or perturbation keep.
    Deep,
    /// Q124 in `i128` with the high halves of 256-bit products (Q120): twice `Deep`'s
    /// bits, at about three times its time on a 64-bit host, down to the same finest
    /// spacing (2⁻⁵⁴). Chosen where the calibration found that neither `Deep` nor
    /// perturbation keeps 99.9 % of dwells: deep views with long orbits near the boundary
    /// (see [`View::new`]). The bits a chaotic orbit needs grow with its length, so at
    /// caps in the tens of thousands even 120 bits miss a few pixels in ten thousand
    /// (docs/tiers.md has the shares).
    Wide,
    /// Perturbation against one reference orbit (see [`ReferenceOrbit`](crate::escape::ReferenceOrbit)):
    /// the reference in up to 192-bit fixed point, each pixel a difference from it in 62-bit
    /// mantissas with an exponent. Chosen for Mandelbrot views finer than `Deep` resolves
    /// (spacing below 2⁻⁵⁴), down to a spacing of 2⁻¹⁴⁸ (a width of about 10⁻⁴² on 320
    /// pixels), and from z = 40 where z + i ≥ 51 at caps up to 2048 (see [`View::new`]);
    /// by hand on any Mandelbrot view. Needs storage for the reference: a render
    /// of it is made with [`Render::perturbed`](crate::escape::Render::perturbed).
    Perturbation,
}

impl Tier {
    /// Every fixed-point tier, narrowest first.
    pub const ALL: [Tier; 5] = [
        Tier::Narrow,
        Tier::Medium,
        Tier::Standard,
        Tier::Deep,
        Tier::Wide,
    ];

    /// Fractional bits of the tier's numbers (a perturbation's pixels keep 62 bits
    /// relative to their distance from the reference; its reference, up to 188).
    pub const fn frac_bits(self) -> u32 {
        match self {
            Self::Narrow => 12,
            Self::Medium | Self::Standard => 28,
            Self::Deep => 60,
            Self::Wide => 124,
            Self::Perturbation => DeepCoord::FRAC_BITS,
        }
    }

    /// Fractional bits an orbit keeps from step to step: the numbers' bits, or fewer where
    /// products are cut shorter (`Medium`).
    pub const fn precision_bits(self) -> u32 {
        match self {
            Self::Medium => 24,
            Self::Wide => 120,
            _ => self.frac_bits(),
        }
    }

    /// The finest pixel spacing the tier tells apart: its unit (2⁻¹², 2⁻²⁴, 2⁻²⁸), and for
    /// `Deep` and `Wide` 2⁻⁵⁴ (their pixels' points are in Q60, keeping 6 bits below it).
    /// Perturbation's, 2⁻¹⁴⁸, is below a [`Coord`]'s unit: 0 here.
    pub const fn finest_spacing(self) -> Coord {
        Coord::from_bits(match self {
            Self::Deep | Self::Wide => FINEST_SPACING,
            Self::Perturbation => 0,
            tier => 1 << (Coord::FRAC_BITS - tier.precision_bits()),
        })
    }

    /// The tier's name, as the CLI spells it.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Narrow => "narrow",
            Self::Medium => "medium",
            Self::Standard => "standard",
            Self::Deep => "deep",
            Self::Wide => "wide",
            Self::Perturbation => "perturbation",
        }
    }
}

/// What a pixel's value is: the palette's input.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Shading {
    /// The dwell: the step at which the orbit left radius 2 (whole numbers, so a gradient
    /// shows bands).
    #[default]
    Dwell,
    /// The normalised iteration count ν = N + 2 − log₂(log₂|z_N|²), taken at the first N
    /// past the escape with |z_N| ≥ 256 so it is continuous across the bands, in
    /// sixteenths of an iteration
    /// ([`SMOOTH_FRACTION_BITS`]): a gradient of 16× the entries shows no bands. Computed
    /// in fixed point with a logarithm table (`log₂`, 64 entries), only for escaping
    /// pixels, once each: no floats, the same bits on every core.
    Smooth,
    /// The estimated distance to the set (see [`View::with_distance`]) on a log scale:
    /// 16 values a doubling, 1 at 1/16 of a pixel, 65 at one pixel, up to 255; the set
    /// [`DISTANCE_INSIDE`] (256). Escaping orbits are computed twice.
    Distance,
}

/// A view: a fractal, a centre, a width along the real axis, and a size in pixels.
///
/// Pixels are square: spacing d = width / W, and pixel (i, j), row 0 at the top, samples
/// c = (re + (i + ½ − W/2)·d, im − (j + ½ − H/2)·d).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct View {
    pub(crate) fractal: Fractal,
    pub(crate) centre: (Coord, Coord),
    pub(crate) spacing: i64,
    pub(crate) size: Size,
    pub(crate) max_iterations: u32,
    pub(crate) tier: Tier,
    /// The tier the automatic rule chose.
    automatic: Tier,
    pub(crate) shading: Shading,
    /// Fractint's `inside=` and `outside=`.
    pub(crate) inside: Inside,
    pub(crate) outside: Outside,
    /// Distance estimation's width in 256ths of a pixel (0: off).
    pub(crate) distance: u16,
    /// The centre and spacing to all the bits given (perturbation's reference and offsets;
    /// the fixed tiers read the Q60 ones above).
    pub(crate) deep_centre: (DeepCoord, DeepCoord),
    pub(crate) deep_spacing: DeepCoord,
}

impl View {
    /// Most iterations a smooth view may ask for: its values are sixteenths of an iteration in
    /// 16 bits.
    pub const MAX_SMOOTH_ITERATIONS: u32 = MAX_SMOOTH_ITERATIONS;

    /// Most iterations a view may ask for (dwells are kept in 16 bits).
    pub const MAX_ITERATIONS: u32 = MAX_ITERATIONS;

    /// Checks a view and picks its tier.
    ///
    /// The tier is the cheapest that keeps at least 99.9 % of dwells identical to an exact
    /// reference (double-double, and a 256-bit model where that runs out of bits), and no
    /// fewer than a naive `f32` loop, over the calibration
    /// views with the same z and i below (pooled by pixels; `cargo bench --bench tiers`
    /// re-derives the rule and writes the evidence to `docs/tiers.md`). Rounding near the
    /// boundary is magnified the longer an orbit runs, so the rule is in the pixel spacing
    /// d and the cap: with z = ⌈log₂(1/d)⌉ and i = ⌈log₂(max-iter)⌉, the Mandelbrot set
    /// takes `Medium` while z + i ≤ 12, `Standard` while z + i ≤ 15; past z + i = 25
    /// with a cap over 256, [`Tier::Wide`] while z < 40 or the cap is over 2048; otherwise
    /// `Deep` up to z + i = 50 and [`Tier::Perturbation`] beyond (render it with
    /// [`Render::perturbed`](crate::escape::Render::perturbed)). A Julia set (all boundary) takes
    /// `Medium` at z = 7, i = 7 (the whole set on a 320-pixel-wide display at 65–128
    /// iterations), `Standard` elsewhere while z + 7·i ≤ 56 (up to 64 iterations at
    /// z ≤ 14, 128 at z ≤ 7), `Deep` while z + i ≤ 22 and the cap is at most 2048, and
    /// `Wide` beyond; all while the
    /// spacing itself is resolvable (≥ 2⁻⁵⁴). `Medium` for that one cell is measured, not
    /// derived: pooled, it keeps 44 more of 921,600 dwells than `f32` there, and a few
    /// fewer at z = 6 and 10; per view it is within 0.04 points of `f32`, either side
    /// (docs/tiers.md).
    pub fn new(
        fractal: Fractal,
        centre: (Coord, Coord),
        width: Coord,
        size: Size,
        max_iterations: u32,
    ) -> Result<Self, Error> {
        if size.width == 0 || size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        if max_iterations == 0 || max_iterations > MAX_ITERATIONS {
            return Err(Error::View(ViewError::IterationsOutOfRange {
                value: max_iterations,
                max: MAX_ITERATIONS,
            }));
        }
        if width.to_bits() <= 0 {
            return Err(Error::View(ViewError::WidthNotPositive { width }));
        }
        let limit = Coord::from_bits(COORDINATE_LIMIT);
        // At most the width, which fits: a Coord is below 8.
        let spacing = i64::try_from(div_round(
            i128::from(width.to_bits()),
            i128::from(size.width),
        ))
        .unwrap_or(i64::MAX);
        if let Fractal::Julia { re, im } = fractal {
            let modulus = i128::from(re.to_bits()).pow(2) + i128::from(im.to_bits()).pow(2);
            if modulus > 4 << 120 {
                return Err(Error::View(ViewError::JuliaParameterTooFar { re, im }));
            }
        }
        let tier = Self::tier_for(fractal, spacing, max_iterations)?;
        let view = Self {
            fractal,
            centre,
            spacing,
            size,
            max_iterations,
            tier,
            automatic: tier,
            shading: Shading::Dwell,
            inside: Inside::MaxIter,
            outside: Outside::Iter,
            distance: 0,
            deep_centre: (
                DeepCoord::from_coord(centre.0),
                DeepCoord::from_coord(centre.1),
            ),
            deep_spacing: DeepCoord::from_coord(Coord::from_bits(spacing)),
        };
        // Every pixel within ±3.5: the corners are the extremes.
        let (w, h) = (i64::from(size.width), i64::from(size.height));
        let reach = [(0, 0), (w - 1, h - 1)]
            .into_iter()
            .map(|(i, j)| {
                let (re, im) = view.point(i, j);
                re.abs().max(im.abs())
            })
            .max()
            .unwrap_or(0);
        if reach > i128::from(limit.to_bits()) {
            let reach = Coord::from_bits(i64::try_from(reach).unwrap_or(i64::MAX));
            return Err(Error::View(ViewError::BeyondLimit { reach, limit }));
        }
        Ok(view)
    }

    /// A view whose centre and width have more bits than a [`Coord`] holds: past `Deep`'s
    /// finest spacing (2⁻⁵⁴) a Mandelbrot view takes [`Tier::Perturbation`], down to a
    /// spacing of 2⁻¹⁴⁸; above it, the same view and tier as [`View::new`] with the centre
    /// and width rounded to Q60 (perturbation by hand still uses every bit).
    pub fn deep(
        fractal: Fractal,
        centre: (DeepCoord, DeepCoord),
        width: DeepCoord,
        size: Size,
        max_iterations: u32,
    ) -> Result<Self, Error> {
        if width.is_negative() || width.is_zero() {
            return Err(Error::View(ViewError::WidthNotPositive {
                width: width.to_coord(),
            }));
        }
        let deep_spacing = width.div_small(size.width.max(1));
        let rounded = (centre.0.to_coord(), centre.1.to_coord());
        let shallow = deep_spacing.to_coord().to_bits() >= FINEST_SPACING;
        let mut view = if shallow {
            Self::new(fractal, rounded, width.to_coord(), size, max_iterations)?
        } else {
            if let Fractal::Julia { .. } = fractal {
                return Err(Error::View(ViewError::PerturbationNeedsMandelbrot));
            }
            let finest = DeepCoord::unit_at(DeepCoord::FRAC_BITS - FINEST_PERTURBATION_BITS);
            if deep_spacing.top_bit() < finest.top_bit() {
                return Err(Error::View(ViewError::PerturbationTooDeep {
                    spacing: deep_spacing,
                    finest,
                }));
            }
            // The checks of `new` on a stand-in of the finest fixed spacing at the same
            // centre: the corners are the centre to far below a unit of Q60.
            let stand_in = Coord::from_bits(FINEST_SPACING * i64::from(size.width));
            let mut view = Self::new(fractal, rounded, stand_in, size, max_iterations)?;
            view.tier = Tier::Perturbation;
            view.automatic = Tier::Perturbation;
            // What a fixed tier forced on it sees: a spacing below its resolution.
            view.spacing = deep_spacing.to_coord().to_bits();
            view
        };
        view.deep_centre = centre;
        view.deep_spacing = deep_spacing;
        Ok(view)
    }

    /// The calibrated rule of [`View::new`].
    fn tier_for(fractal: Fractal, spacing: i64, max_iterations: u32) -> Result<Tier, Error> {
        if spacing < FINEST_SPACING {
            return Err(Error::View(ViewError::ZoomTooDeep {
                spacing: Coord::from_bits(spacing),
                finest: Coord::from_bits(FINEST_SPACING),
            }));
        }
        let (zoom_bits, iteration_bits) = rule_bits(spacing, max_iterations);
        Ok(match fractal {
            Fractal::Mandelbrot if zoom_bits + iteration_bits <= 12 => Tier::Medium,
            // The whole set on a 480- or 800-pixel display at 129–256 iterations (z = 8,
            // i = 8) meets the rule in `Standard` too, calibrated like the rest
            // (docs/tiers.md).
            Fractal::Mandelbrot
                if zoom_bits + iteration_bits <= 15 || (zoom_bits, iteration_bits) == (8, 8) =>
            {
                Tier::Standard
            }
            // Long orbits of deep views: past z + i = 25 at caps over 256, `Deep`'s 60 bits
            // lose dwells near the boundary, and so do perturbation's 62-bit differences
            // from an exact reference while z < 40, or at caps over 2048 (docs/tiers.md).
            Fractal::Mandelbrot
                if iteration_bits > 8
                    && zoom_bits + iteration_bits > DEEP_UNTIL
                    && (zoom_bits < WIDE_BELOW || iteration_bits >= LONG_ORBIT) =>
            {
                Tier::Wide
            }
            // Near `Deep`'s finest spacing, and from z = 40 at caps up to 2048, perturbation
            // keeps the dwells `Deep` loses.
            Fractal::Mandelbrot if zoom_bits + iteration_bits >= PERTURBATION_FROM => {
                Tier::Perturbation
            }
            // Rounded 24 bits keep more dwells than f32 on the pool at z = 7, i = 7 (the
            // whole set on a 320-pixel display at 65–128 iterations); elsewhere the pools
            // need `Standard`, or single views at caps up to 64 lose a pixel or a few. At
            // z = 8, i = 7 (the whole set on a 480- or 800-pixel display at 65–128
            // iterations) `Medium` holds on the pool but not on every view: `Standard`.
            Fractal::Julia { .. } if zoom_bits == 7 && iteration_bits == 7 => Tier::Medium,
            Fractal::Julia { .. }
                if zoom_bits + 7 * iteration_bits <= 56
                    || (zoom_bits, iteration_bits) == (8, 7) =>
            {
                Tier::Standard
            }
            Fractal::Julia { .. }
                if zoom_bits + iteration_bits > JULIA_DEEP_UNTIL
                    || iteration_bits >= LONG_ORBIT =>
            {
                Tier::Wide
            }
            _ => Tier::Deep,
        })
    }

    /// Computes in `tier` instead of the automatic choice (coarser tiers are faster and less
    /// exact; a finer one is never wrong).
    #[must_use]
    pub const fn with_tier(mut self, tier: Tier) -> Self {
        self.tier = tier;
        self
    }

    /// Gives each pixel the value `shading` says (dwells by default). Smooth values are
    /// sixteenths of an iteration in 16 bits, so a smooth view's cap is at most
    /// [`View::MAX_SMOOTH_ITERATIONS`].
    pub fn with_shading(mut self, shading: Shading) -> Result<Self, Error> {
        if shading != Shading::Dwell && self.outside != Outside::Iter {
            return Err(Error::View(ViewError::OutsideModeWithSmooth));
        }
        if shading == Shading::Smooth && self.max_iterations > MAX_SMOOTH_ITERATIONS {
            return Err(Error::View(ViewError::SmoothIterationsOutOfRange {
                value: self.max_iterations,
                max: MAX_SMOOTH_ITERATIONS,
            }));
        }
        self.shading = shading;
        Ok(self)
    }

    /// What a pixel's value is.
    pub const fn shading(&self) -> Shading {
        self.shading
    }

    /// Values pixels that never escape as Fractint's `inside=` mode does (the cap, the
    /// palette's inside colour, by default). Any mode but `MaxIter` runs every inside orbit
    /// to the cap, with neither the cardioid test nor the repeat test (its value is z
    /// there), and draws a Mandelbrot view by subdivision rather than by tracing.
    #[must_use]
    pub const fn with_inside(mut self, inside: Inside) -> Self {
        self.inside = inside;
        self
    }

    /// Values escaping pixels as Fractint's `outside=` mode does (their dwell, by
    /// default). `Imag`, `Mult` and `Summ` differ between c and its conjugate, so a view on
    /// the real axis is computed whole instead of mirrored. Outside modes colour dwells:
    /// with smooth shading, an error.
    pub fn with_outside(mut self, outside: Outside) -> Result<Self, Error> {
        if outside != Outside::Iter && self.shading != Shading::Dwell {
            return Err(Error::View(ViewError::OutsideModeWithSmooth));
        }
        self.outside = outside;
        Ok(self)
    }

    /// Draws every escaping pixel whose estimated distance to the set, d ≈ |z|·ln|z| /
    /// |dz/dc| (|dz/dz₀| for a Julia set), is below `width_256ths`/256 of a pixel as the
    /// set; 0 turns it off. Fractint's default is 0.71 of a pixel (182/256). Strands
    /// thinner than a pixel then stay connected, on a one-bit panel too. Such a pixel's
    /// value is one above the inside value (at most 65,535): every palette paints values
    /// from the inside value up as the set, and the render tells it from the set itself.
    ///
    /// Each escaping orbit is run again with its derivative (see the `distance` module),
    /// and tracing is off. `Fast` fills a block whose border is all inside the set (the set
    /// is full, so its pixels are too), and a block whose border escapes with one dwell only
    /// where every border pixel's estimate proves the set so far (Koebe's quarter theorem
    /// bounds the true distance by the estimate, within the view's ±3.5) that no pixel
    /// inside is within the width: elsewhere a strand may cross it, and its pixels are
    /// computed. Not with the distance shading, whose values vary with the distance.
    /// A perturbed render's pixels carry dz beside their differences instead, from the
    /// series' derivative at the skip, each step from the full point Zₘ + δ.
    #[must_use]
    pub const fn with_distance(mut self, width_256ths: u16) -> Self {
        self.distance = width_256ths;
        self
    }

    /// Distance estimation's width in 256ths of a pixel (0: off).
    pub const fn distance(&self) -> u16 {
        self.distance
    }

    /// Whether escaping orbits are run again for their distance: a width or distance
    /// shading.
    pub(crate) fn estimates_distance(&self) -> bool {
        self.distance != 0 || self.shading == Shading::Distance
    }

    /// Fractint's `inside=` mode.
    pub const fn inside(&self) -> Inside {
        self.inside
    }

    /// Fractint's `outside=` mode.
    pub const fn outside(&self) -> Outside {
        self.outside
    }

    /// This view with dwells alone: no smooth shading, modes or distance estimation.
    #[must_use]
    pub const fn dwells_only(mut self) -> Self {
        self.shading = Shading::Dwell;
        self.inside = Inside::MaxIter;
        self.outside = Outside::Iter;
        self.distance = 0;
        self
    }

    /// The value of a pixel that did not escape: the cap, or the cap in sixteenths when
    /// smooth. Every escaping pixel's value is below it and above 0.
    pub const fn inside_value(&self) -> u16 {
        let value = match self.shading {
            Shading::Dwell => self.max_iterations,
            Shading::Smooth => self.max_iterations << SMOOTH_FRACTION_BITS,
            Shading::Distance => DISTANCE_INSIDE as u32,
        };
        if value > u16::MAX as u32 {
            u16::MAX
        } else {
            value as u16
        }
    }

    /// The tier this view computes in.
    pub const fn tier(&self) -> Tier {
        self.tier
    }

    /// The tier the automatic rule picks for this view (the one [`View::new`] chose).
    pub const fn automatic_tier(&self) -> Tier {
        self.automatic
    }

    /// Whether the tier tells neighbouring pixels apart: the pixel spacing is at least its
    /// [`finest_spacing`](Tier::finest_spacing). If not, as for `Narrow` at a width of
    /// 10⁻⁴ or `Standard` at 5·10⁻⁹ on 320 pixels, whole blocks of pixels share one point
    /// and the picture comes out in blocks or flat. The automatic tier always does; a forced one may not, and the CLI
    /// warns then.
    pub const fn resolves_pixels(&self) -> bool {
        matches!(self.tier, Tier::Perturbation)
            || self.spacing >= self.tier.finest_spacing().to_bits()
    }

    /// The size in pixels.
    pub const fn size(&self) -> Size {
        self.size
    }

    /// The iteration cap: a dwell of this value means "did not escape".
    pub const fn max_iterations(&self) -> u32 {
        self.max_iterations
    }

    /// The fractal.
    pub const fn fractal(&self) -> Fractal {
        self.fractal
    }

    /// The centre (real, imaginary), rounded to Q60.
    pub const fn centre(&self) -> (Coord, Coord) {
        self.centre
    }

    /// The centre with every bit given (what perturbation's reference orbit starts from).
    pub const fn deep_centre(&self) -> (DeepCoord, DeepCoord) {
        self.deep_centre
    }

    /// The pixel spacing with every bit kept.
    pub const fn deep_spacing(&self) -> DeepCoord {
        self.deep_spacing
    }

    /// Pixel spacing in Q60 bits.
    pub const fn spacing(&self) -> Coord {
        Coord::from_bits(self.spacing)
    }

    /// The sample point of pixel (i, j) in Q60 bits, as i128 (it may be out of range for
    /// pixels outside the view). Offsets are rounded half away from zero, so rows mirrored
    /// about a centre on the real axis get exactly negated imaginary parts.
    pub(crate) fn point(&self, i: i64, j: i64) -> (i128, i128) {
        (self.column(i), self.row(j))
    }

    /// The real part of column i's points (Q60): points are a column part and a row part,
    /// so a render can compute each once per tile instead of once per pixel.
    pub(crate) fn column(&self, i: i64) -> i128 {
        i128::from(self.centre.0.to_bits()) + self.offset(self.column_steps(i))
    }

    /// The imaginary part of row j's points (Q60).
    pub(crate) fn row(&self, j: i64) -> i128 {
        i128::from(self.centre.1.to_bits()) + self.offset(self.row_steps(j))
    }

    /// [`column`](Self::column) of columns i, i + 1, … while in the view, as i64: one
    /// wide product for the first, an addition for each after it.
    pub(crate) fn columns_from(&self, i: i64) -> Parts {
        Parts::new(
            self.centre.0.to_bits(),
            self.spacing,
            self.column_steps(i),
            2,
        )
    }

    /// [`row`](Self::row) of rows j, j + 1, … (downwards) while in the view, as i64.
    pub(crate) fn rows_from(&self, j: i64) -> Parts {
        Parts::new(self.centre.1.to_bits(), self.spacing, self.row_steps(j), -2)
    }

    /// Column i's real offset from the centre in half spacings: 2i + 1 − W.
    pub(crate) const fn column_steps(&self, i: i64) -> i64 {
        2 * i + 1 - self.size.width as i64
    }

    /// Row j's imaginary offset from the centre in half spacings: H − 2j − 1 (up).
    pub(crate) const fn row_steps(&self, j: i64) -> i64 {
        self.size.height as i64 - 2 * j - 1
    }

    fn offset(&self, k: i64) -> i128 {
        half_spacings(self.spacing, k)
    }

    /// Whether the fixed-point tiers resolve the view's pixels (its spacing is at least
    /// `Deep`'s finest, 2⁻⁵⁴).
    pub(crate) const fn fixed_point_resolves(&self) -> bool {
        self.spacing >= FINEST_SPACING
    }

    /// Which pixels are the same by symmetry, exactly (see the kernel's rounding).
    pub(crate) const fn symmetry(&self) -> Symmetry {
        match self.fractal {
            // c and its conjugate have the same dwell.
            Fractal::Mandelbrot
                if self.centre.1.to_bits() == 0
                    && self.deep_centre.1.is_zero()
                    && self.outside.symmetric() =>
            {
                Symmetry::MirrorRows
            }
            // z0 and -z0 have the same z1, so the same dwell.
            Fractal::Julia { .. }
                if self.centre.0.to_bits() == 0 && self.centre.1.to_bits() == 0 =>
            {
                Symmetry::HalfTurn
            }
            _ => Symmetry::None,
        }
    }
}

/// The rule's inputs: z = ⌈log₂(1/d)⌉ for a spacing d in Q60 bits (0 for pixels 2 or
/// more wide) and i = ⌈log₂(max-iter)⌉.
const fn rule_bits(spacing: i64, max_iterations: u32) -> (u32, u32) {
    let zoom_bits = 60u32.saturating_sub(63 - spacing.leading_zeros());
    let iteration_bits = 32 - max_iterations.saturating_sub(1).leading_zeros();
    (zoom_bits, iteration_bits)
}

/// `k` half spacings (`spacing` in Q60), rounded half away from zero, as every tier's
/// pixel offsets are.
pub(crate) fn half_spacings(spacing: i64, k: i64) -> i128 {
    shift_round(mul_wide(spacing, k), 1)
}

/// The Q60 parts of consecutive columns or rows. Offsets are half spacings rounded half
/// away from zero, so two steps further on one side of the centre is exactly one spacing
/// further; across the centre (1 to −1 half spacings) the offset is negated. Exact while
/// in the view (parts within ±3.5, offsets within ±7); past it the values wrap and are
/// not used.
#[derive(Debug, Clone)]
pub(crate) struct Parts {
    centre: i64,
    /// The next part's offset from the centre, and that offset in half spacings.
    offset: i64,
    steps: i64,
    /// Half spacings from one part to the next (±2), and the offset that adds on one side.
    stride: i64,
    spacing: i64,
}

impl Parts {
    /// The next part's offset in half spacings, and what each part after adds to it.
    pub(crate) const fn steps(&self) -> (i64, i64) {
        (self.steps, self.stride)
    }

    fn new(centre: i64, spacing: i64, steps: i64, stride: i64) -> Self {
        Self {
            centre,
            offset: i64::try_from(half_spacings(spacing, steps)).unwrap_or(0),
            steps,
            stride,
            spacing: if stride < 0 {
                spacing.wrapping_neg()
            } else {
                spacing
            },
        }
    }
}

impl Iterator for Parts {
    type Item = i64;

    #[inline(always)]
    fn next(&mut self) -> Option<i64> {
        let part = self.centre.wrapping_add(self.offset);
        let next = self.steps.wrapping_add(self.stride);
        self.offset = if next == self.steps.wrapping_neg() {
            self.offset.wrapping_neg()
        } else {
            self.offset.wrapping_add(self.spacing)
        };
        self.steps = next;
        Some(part)
    }
}

/// A symmetry of a view's pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Symmetry {
    /// None used.
    None,
    /// Pixel (i, j) equals (i, H−1−j): a Mandelbrot view centred on the real axis.
    MirrorRows,
    /// Pixel (i, j) equals (W−1−i, H−1−j): a Julia view centred on the origin.
    HalfTurn,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Parts found by additions equal the product for each, on both sides of the centre
    /// and across it, for odd spacings (where rounding half away from zero makes the
    /// step across the centre one unit longer) and even ones, both directions, as long
    /// as the offsets and parts fit an i64 (a view's are within ±7 and ±3.5 in Q60).
    #[test]
    fn parts_by_addition_equal_parts_by_product() {
        let spacings = [1, 3, 2, 7, 1 << 20, (1 << 53) + 1, 3 << 58, (1 << 60) + 1];
        let centres = [0, 1, -1, 5 << 58, -(3 << 59) + 7];
        let mut compared = 0;
        for spacing in spacings {
            for centre in centres {
                for first in -41..=40i64 {
                    for stride in [2, -2] {
                        let parts = Parts::new(centre, spacing, first, stride);
                        for (k, part) in (0..80).zip(parts) {
                            let offset = half_spacings(spacing, first + stride * k);
                            if i64::try_from(offset).is_err() {
                                break;
                            }
                            let Ok(expected) = i64::try_from(i128::from(centre) + offset) else {
                                continue;
                            };
                            assert_eq!(part, expected, "{spacing} {centre} {first} {stride} {k}");
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert!(compared > 250_000, "{compared}");
    }
}
