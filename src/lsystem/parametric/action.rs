//! What a derived module does to a turtle: the one reading of ABOP's symbols that the 2D,
//! the 3D and the matrix turtle share (`F(l)`, `f(l)`, `G(l)`, `r`, `R`, colours, widths,
//! polygons, `[`, `]`), and the 2D turtle's commands, turns included.

use super::values::DerivedModule;
use crate::lsystem::alphabet::Command;
use crate::math::trig::BinaryAngle;
use crate::math::Real;

/// √2, the lecture's `R` (Q32).
const SQRT_2: Real = Real::from_bits(6_074_001_000);
/// 1/√2, the lecture's `r` (Q32).
const INV_SQRT_2: Real = Real::from_bits(3_037_000_500);

/// A change of the colour index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ColorChange {
    Set(u8),
    Raise,
    Lower,
}

impl ColorChange {
    pub(crate) fn apply(self, color: u8) -> u8 {
        match self {
            Self::Set(c) => c,
            Self::Raise => color.wrapping_add(1),
            Self::Lower => color.wrapping_sub(1),
        }
    }
}

/// A change of the line width: `!(w)` and `_(w)` set it, `!` lowers it and `_` raises it
/// by the system's width step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum WidthChange {
    Set(Real),
    Lower,
    Raise,
}

/// What a module makes the 2D and the 3D turtle alike do (turns differ).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Action {
    /// `F(l)`, `f(l)`, `G(l)`: `length` steps, drawing a line or not; in a polygon none
    /// draws, and `G` records no vertex.
    Step {
        length: Real,
        draw: bool,
        vertex: bool,
    },
    /// `r` and `R`: the step times 1/√2 or √2 (the lecture's scale symbols).
    Scale(Real),
    /// `'(c)`, `;(c)`, `,(c)` set the colour index; `'` (ABOP) and `;` (cpfg) raise it,
    /// `,` lowers it.
    Color(ColorChange),
    Push,
    Pop,
    /// `!`, `_`: the line width.
    Width(WidthChange),
    /// `{`: a polygon starts.
    StartPolygon,
    /// `.`: the turtle's position is a vertex of the polygon.
    Vertex,
    /// `}`: the polygon closes and is filled.
    EndPolygon,
    /// Anything else.
    Nothing,
}

/// What a derived module makes any turtle do, turns aside.
pub(crate) fn turtle_action(module: &DerivedModule) -> Action {
    let value = module.values.first();
    let color = |c: Real| u8::try_from(c.round_to_i32().clamp(0, 255)).unwrap_or(0);
    match (module.symbol, value) {
        ('F' | 'f' | 'G', length) => Action::Step {
            length: length.unwrap_or(Real::ONE),
            draw: module.symbol != 'f',
            vertex: module.symbol != 'G',
        },
        ('r', _) => Action::Scale(INV_SQRT_2),
        ('R', _) => Action::Scale(SQRT_2),
        ('\'' | ';' | ',', Some(c)) => Action::Color(ColorChange::Set(color(c))),
        ('\'' | ';', None) => Action::Color(ColorChange::Raise),
        (',', None) => Action::Color(ColorChange::Lower),
        ('!' | '_', Some(width)) => Action::Width(WidthChange::Set(width)),
        ('!', None) => Action::Width(WidthChange::Lower),
        ('_', None) => Action::Width(WidthChange::Raise),
        ('{', _) => Action::StartPolygon,
        ('.', _) => Action::Vertex,
        ('}', _) => Action::EndPolygon,
        ('[', _) => Action::Push,
        (']', _) => Action::Pop,
        _ => Action::Nothing,
    }
}

/// What the 2D turtle does for a derived module.
pub(crate) fn command(module: &DerivedModule) -> Command {
    let value = module.values.first();
    let turn = |degrees: Real| BinaryAngle::from_degrees_bits(degrees.to_bits());
    match (module.symbol, value) {
        ('+', None) => Command::Left,
        ('+', Some(degrees)) => Command::FreeLeft(turn(degrees)),
        ('-', None) => Command::Right,
        ('-', Some(degrees)) => Command::FreeRight(turn(degrees)),
        ('|', _) => Command::Around,
        _ => match turtle_action(module) {
            Action::Step { draw: true, .. } if value.is_none() => Command::Draw,
            Action::Step { draw: false, .. } if value.is_none() => Command::Move,
            Action::Step {
                length, draw: true, ..
            } => Command::DrawBy(length),
            Action::Step {
                length,
                draw: false,
                ..
            } => Command::MoveBy(length),
            Action::Scale(factor) => Command::Scale(factor),
            Action::Color(ColorChange::Set(c)) => Command::SetColor(c),
            Action::Color(ColorChange::Raise) => Command::RaiseColor(1),
            Action::Color(ColorChange::Lower) => Command::LowerColor(1),
            Action::Push => Command::Push,
            Action::Pop => Command::Pop,
            // Systems that use them are drawn by the 3D turtle.
            Action::Width(_)
            | Action::StartPolygon
            | Action::Vertex
            | Action::EndPolygon
            | Action::Nothing => Command::Nothing,
        },
    }
}
