//! What the subdivision fractals share: orders and their powers, the highest order a
//! target resolves, and the depth-first walk over cells with a bounded stack.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError, ParameterError};

/// Deepest subdivision order any of these generators accepts (the explicit stacks' size).
/// A target limits it further: every cell must be at least a pixel.
pub const MAX_SUBDIVISION_ORDER: u32 = 12;

/// `base` to the power `order`, saturating.
pub(crate) const fn power(base: u64, order: u32) -> u64 {
    let mut value: u64 = 1;
    let mut i = 0;
    while i < order {
        value = value.saturating_mul(base);
        i += 1;
    }
    value
}

/// The highest order whose `base`ᵒʳᵈᵉʳ cells across fit in `pixels` (each at least a pixel),
/// capped at [`MAX_SUBDIVISION_ORDER`].
pub(crate) fn highest_order(base: u64, pixels: u64) -> u32 {
    let mut order = 0;
    while order < MAX_SUBDIVISION_ORDER && power(base, order + 1) <= pixels {
        order += 1;
    }
    order
}

/// Checks `order` against what `pixels` across (and the capacity) allow.
pub(crate) fn check_order(order: u32, base: u64, pixels: u64) -> Result<(), Error> {
    let max = highest_order(base, pixels);
    if order > max {
        return Err(Error::Parameter(ParameterError::OrderTooHigh {
            order,
            max,
        }));
    }
    Ok(())
}

/// Depth first over a subdivision `order` (≥ 1) levels deep, with an explicit stack of
/// child indices, one per level: `visit(level, parent, child)` is called for each child
/// `0..children` of each cell descended into, in order, and returns the child's cell to
/// descend into (taken only above the last level) or `None`. The root is
/// `T::default()`. Shared by the carpet (9 children) and the cube (27).
pub(crate) fn depth_first<T: Copy + Default, E>(
    order: u32,
    children: u8,
    mut visit: impl FnMut(u32, T, u8) -> Result<Option<T>, E>,
) -> Result<(), E> {
    let mut next_child = [0u8; MAX_SUBDIVISION_ORDER as usize];
    let mut cell = [T::default(); MAX_SUBDIVISION_ORDER as usize];
    let mut depth = 0usize;
    while let (Some(child), Some(&parent)) = (next_child.get_mut(depth), cell.get(depth)) {
        if *child == children {
            if depth == 0 {
                break;
            }
            depth -= 1;
            continue;
        }
        let index = *child;
        *child += 1;
        let level = depth as u32 + 1;
        let Some(at) = visit(level, parent, index)? else {
            continue;
        };
        if level < order {
            if let (Some(slot), Some(first)) =
                (cell.get_mut(depth + 1), next_child.get_mut(depth + 1))
            {
                *slot = at;
                *first = 0;
                depth += 1;
            }
        }
    }
    Ok(())
}

/// The largest square centred in `area`.
pub(crate) fn centred_square(area: Rectangle) -> Result<Rectangle, Error> {
    let side = area.size.width.min(area.size.height);
    if side == 0 {
        return Err(Error::Fit(FitError::ZeroSizeTarget));
    }
    let offset = Point::new(
        ((area.size.width - side) / 2) as i32,
        ((area.size.height - side) / 2) as i32,
    );
    Ok(Rectangle::new(
        area.top_left + offset,
        Size::new(side, side),
    ))
}
