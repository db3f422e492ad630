//! What every fuzz target shares: a target that fails on any pixel outside it, small
//! caps that keep each input well under libFuzzer's time limit, and the drawing of every
//! kind of grammar the readers give.

use core::convert::Infallible;

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use tinyfractal::{
    lsystem::{cells_needed, Cell, Walker, DEFAULT_DEPTH, DEFAULT_STACK},
    render::{Colors, DwellSink},
    Grammar, LSystem, ParametricGrammar, ParametricLSystem,
};

/// Symbols a walk may read per input: a fuzz input must stay well under a second.
pub const BUDGET: u64 = 20_000;

/// The colours drawn with.
pub const PALETTE: [Rgb888; 3] = [Rgb888::WHITE, Rgb888::RED, Rgb888::GREEN];

/// A display that panics (a crash for the fuzzer) on any pixel outside its bounds: the
/// core promises never to draw there.
pub struct StrictTarget {
    size: Size,
    /// Pixels drawn, so the work is not optimised away.
    pub drawn: u64,
}

impl StrictTarget {
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            size: Size::new(width, height),
            drawn: 0,
        }
    }

    fn check(&mut self, point: Point) {
        let inside = point.x >= 0
            && point.y >= 0
            && (point.x as u32) < self.size.width
            && (point.y as u32) < self.size.height;
        assert!(inside, "a pixel at {point:?} outside {:?}", self.size);
        self.drawn += 1;
    }
}

impl OriginDimensions for StrictTarget {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for StrictTarget {
    type Color = Rgb888;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(point, _) in pixels {
            self.check(point);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb888>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        let mut colors = colors.into_iter();
        for point in area.points() {
            self.check(point);
            assert!(
                colors.next().is_some(),
                "fewer colours than {area:?} has pixels"
            );
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, _: Rgb888) -> Result<(), Infallible> {
        if let Some(corner) = area.bottom_right() {
            self.check(area.top_left);
            self.check(corner);
        }
        Ok(())
    }
}

/// A dwell sink that panics on a value outside 1..=`inside` or an area outside the view.
pub struct StrictDwells {
    pub size: Size,
    pub inside: u16,
}

impl DwellSink for StrictDwells {
    type Error = Infallible;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Infallible> {
        let view = Rectangle::new(Point::zero(), self.size);
        assert!(
            view.contains(area.top_left) && area.bottom_right().is_none_or(|p| view.contains(p)),
            "{area:?} outside {view:?}"
        );
        let mut count = 0u64;
        for value in dwells.take(area.points().count()) {
            assert!(
                value >= 1 && value <= self.inside,
                "value {value} of {}",
                self.inside
            );
            count += 1;
        }
        assert_eq!(
            count,
            u64::from(area.size.width) * u64::from(area.size.height)
        );
        Ok(())
    }
}

/// Draws a plain grammar at `order` into a strict 64×48 target, by walking and through
/// the expansion table (when it needs a few cells only).
pub fn draw_plain(grammar: &Grammar<'_>, order: u32) {
    let mut target = StrictTarget::new(64, 48);
    let system = LSystem::new(grammar, order).with_budget(BUDGET);
    if let Ok(drawing) = system.fit(target.bounding_box(), &PALETTE) {
        let _ = drawing.draw(&mut target);
    }
    if let (Some(cells), Some(palette)) = (cells_needed(grammar, order), Colors::new(&PALETTE)) {
        let mut storage = vec![Cell::default(); cells.min(4096)];
        let mut target = StrictTarget::new(64, 48);
        if let Ok(drawing) = system.fit_in(target.bounding_box(), palette, &mut storage) {
            let _ = drawing.draw(&mut target);
        }
    }
}

/// Derives a plain grammar at `order` (as `derive` does, for a system read without an
/// angle too): at most [`BUDGET`] symbols, each written out.
pub fn derive_plain(grammar: &Grammar<'_>, order: u32) {
    let Ok(walker) = Walker::<'_, '_, DEFAULT_DEPTH>::with_capacity(grammar, order) else {
        return;
    };
    let mut walker = walker.with_budget(BUDGET);
    let mut text = String::new();
    while let Some(symbol) = walker.next_symbol() {
        let Ok(symbol) = symbol else { break };
        text = symbol.to_string();
    }
    assert!(text.len() < 1 << 16);
}

/// Draws a parametric grammar at `order` into a strict target.
pub fn draw_parametric(grammar: &ParametricGrammar, order: u32) {
    let mut target = StrictTarget::new(64, 48);
    if let Ok(drawing) = ParametricLSystem::<'_, DEFAULT_DEPTH, DEFAULT_STACK>::new(grammar, order)
        .with_budget(BUDGET)
        .fit(target.bounding_box(), &PALETTE)
    {
        let _ = drawing.draw(&mut target);
    }
}
