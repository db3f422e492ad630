//! The CLI's built-in worlds for open L-systems (`--environment`): a region a plant may
//! grow in, standing on the turtle's start, as in ABOP's topiary.

use tinyfractal::{
    lsystem::{Environment, TurtleState},
    Real,
};

/// A region, `size` turtle units across its height scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A circle of radius `r` whose lowest point is the turtle's start.
    Circle(f64),
    /// A heart `r` wide at each lobe whose tip is the turtle's start.
    Heart(f64),
}

impl Shape {
    /// `circle:R` or `heart:R`.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (name, size) = text
            .split_once(':')
            .ok_or_else(|| format!("`{text}`: give SHAPE:R, e.g. circle:20 or heart:20"))?;
        let size: f64 = size
            .parse()
            .ok()
            .filter(|r: &f64| r.is_finite() && *r > 0.0)
            .ok_or_else(|| format!("`{size}` is not a positive size"))?;
        match name {
            "circle" => Ok(Self::Circle(size)),
            "heart" => Ok(Self::Heart(size)),
            other => Err(format!("unknown shape `{other}`: give circle or heart")),
        }
    }

    /// Whether a point of the picture plane is inside.
    pub fn contains(self, x: f64, y: f64) -> bool {
        match self {
            Self::Circle(r) => x * x + (y - r) * (y - r) <= r * r,
            Self::Heart(r) => {
                // (u² + v² − 1)³ ≤ u²v³, its tip (0, −1) on the start.
                let (u, v) = (x / r, y / r - 1.0);
                (u * u + v * v - 1.0).powi(3) <= u * u * v * v * v
            }
        }
    }
}

/// `env(0)` is 1 where the turtle is inside the shape, else 0; other queries are 0.
impl Environment for Shape {
    fn query(&self, query: Real, turtle: &TurtleState) -> Real {
        let [x, y, _] = turtle.position.map(Real::to_f64);
        if query == Real::ZERO && self.contains(x, y) {
            Real::ONE
        } else {
            Real::ZERO
        }
    }
}
