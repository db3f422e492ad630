//! The fixed-point turtle: a state, a stack of saved states, and the commands that move it.

use heapless::Vec;

use super::alphabet::{Command, Dialect};
use super::table::Summary;
use crate::error::{Error, ReadError, WalkError};
use crate::math::angle::Headings;
use crate::math::trig::BinaryAngle;
use crate::math::wide::shift_round;
use crate::math::Real;

/// Branches the turtle stack holds by default.
pub const DEFAULT_STACK: usize = 20;

/// The smallest step, as a fraction of a unit: 2⁻²⁰. Below it a step keeps fewer than 12
/// significant bits and a measurement in these units would be silently wrong, so it is an
/// error instead: the fit then measures again in a larger unit. A walk in pixels (see
/// `Segments::in_pixels`) takes any step: each rounds by at most 2⁻³³ pixel.
const MIN_STEP: Real = Real::from_bits(1 << 12);

/// A point in turtle space: y up, `+` turns counter-clockwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct TurtlePoint {
    /// Horizontal coordinate.
    pub x: Real,
    /// Vertical coordinate (up).
    pub y: Real,
}

/// One drawn line, in turtle space.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Segment {
    /// Where the line starts.
    pub start: TurtlePoint,
    /// Where it ends.
    pub end: TurtlePoint,
    /// The colour index (`C`, `<`, `>` in Fractint files; 0 unless set).
    pub color: u8,
}

/// Where the turtle starts, how long a step is, and where it heads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Start {
    /// The first position.
    pub position: TurtlePoint,
    /// The length of one step, times 2^`step_shift`.
    pub step: Real,
    /// The step is `step`·2^−`step_shift`: a fitted picture whose first steps are far
    /// below a pixel (an `@` system that grows by many orders of magnitude) keeps their
    /// precision. 0 unless a fit sets it.
    pub step_shift: u32,
    /// The first heading, in turns of the system's angle counter-clockwise from +x (as if
    /// the axiom began with that many `+`).
    pub turns: i32,
}

impl Default for Start {
    /// At the origin, step 1, heading along +x: turtle units.
    fn default() -> Self {
        Self {
            position: TurtlePoint::default(),
            step: Real::ONE,
            step_shift: 0,
            turns: 0,
        }
    }
}

impl Start {
    /// Whether the first step is 0 or below 2⁻²⁰ of a unit ([`WalkError::StepTooFine`]
    /// for a walk in turtle units, and for a fitted or placed picture whose walk is not
    /// short enough for its rounding to stay below a pixel).
    pub(crate) fn too_fine(&self) -> bool {
        Step::new(self.step, self.step_shift).too_fine()
    }
}

/// Shifts past this make a step 0, as a float's exponent runs out (a double's at about
/// 2⁻¹⁰⁷⁴, a float's at 2⁻¹⁴⁹): a saved turtle keeps the shift in a byte.
const MAX_STEP_SHIFT: u32 = u8::MAX as u32;

/// A step length with the dynamic range `@` needs: mantissa·2^−shift, the mantissa in
/// [1, 2) whenever the shift is above 0, so a step shrunk by many orders of magnitude
/// keeps 32 significant bits and grows back exactly by the inverse factors (Fractint's
/// float turtle draws such spirals; a fixed-point step would round to nothing). With a
/// shift of 0 it is the plain `Real` the turtle always had.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Step {
    mantissa: Real,
    shift: u32,
}

impl Step {
    const ZERO: Self = Self {
        mantissa: Real::ZERO,
        shift: 0,
    };

    /// `value`·2^−`shift`, normalised.
    fn new(value: Real, shift: u32) -> Self {
        // A `Real` at any shift fits: normalising only shifts it into [1, 2).
        Self::from_q64(i128::from(value.to_bits()) << 32, shift).unwrap_or(Self::ZERO)
    }

    /// `value` (Q64)·2^−`shift`, with as much of the shift as keeps the mantissa in
    /// [1, 2), rounded once to its 32 fractional bits (half away from zero, as
    /// `Real::checked_mul` rounds); 0 where the shift would pass [`MAX_STEP_SHIFT`].
    /// `None` where it is too large for a `Real` at a shift of 0.
    #[inline(never)]
    fn from_q64(value: i128, shift: u32) -> Option<Self> {
        if value == 0 {
            return Some(Self::ZERO);
        }
        // 1.0 is bit 64 of a Q64 value.
        let top = 127 - value.unsigned_abs().leading_zeros();
        let (mantissa, shift) = if top < 64 {
            let up = 64 - top;
            if shift.saturating_add(up) > MAX_STEP_SHIFT {
                return Some(Self::ZERO);
            }
            (shift_round(value << up, 32), shift + up)
        } else {
            let down = (top - 64).min(shift);
            (shift_round(value, 32 + down), shift - down)
        };
        // Rounding up to 2.0 exactly: halved, exactly, where there is a shift to give.
        let (mantissa, shift) = if shift > 0 && mantissa.unsigned_abs() >= 2 << 32 {
            (mantissa / 2, shift - 1)
        } else {
            (mantissa, shift)
        };
        let mantissa = Real::from_bits(i64::try_from(mantissa).ok()?);
        Some(Self { mantissa, shift })
    }

    /// This step times `factor`; `None` past the `Real` range. Out of line, as `@` and the
    /// lengths are rare beside steps: in the walks' copies of the turtle it cost the
    /// LM3S6965 firmware kilobytes of flash.
    #[inline(never)]
    fn times(self, factor: Real) -> Option<Self> {
        let product = i128::from(self.mantissa.to_bits()) * i128::from(factor.to_bits());
        Self::from_q64(product, self.shift)
    }

    /// Whether this step is 0 or below [`MIN_STEP`] (see [`Start::too_fine`]).
    fn too_fine(self) -> bool {
        self == Self::ZERO || self.below(MIN_STEP)
    }

    /// Whether this step is not 0 and below `min` (not 0) in size.
    fn below(self, min: Real) -> bool {
        let magnitude = u128::from(self.mantissa.to_bits().unsigned_abs());
        let min = u128::from(min.to_bits().unsigned_abs());
        magnitude != 0 && min != 0 && (self.shift >= 65 || magnitude < min << self.shift)
    }

    /// The vector one step moves by along `(cos, sin)` (Q30): each part rounded once,
    /// half away from zero, so mirror images stay exact (see [`scaled`]).
    #[inline(always)]
    fn vector(self, direction: (i32, i32)) -> (Real, Real) {
        if self.shift == 0 {
            return scaled(self.mantissa, direction);
        }
        self.shifted_vector(direction)
    }

    /// [`vector`](Self::vector) of a shifted step, out of line (see [`times`](Self::times)).
    #[cold]
    #[inline(never)]
    fn shifted_vector(self, direction: (i32, i32)) -> (Real, Real) {
        // |mantissa·cos| < 2⁶⁵: from a total shift of 67 every part rounds to 0.
        if self.shift > 36 {
            return (Real::ZERO, Real::ZERO);
        }
        let part = |cos: i32| {
            let product = i128::from(self.mantissa.to_bits()) * i128::from(cos);
            Real::from_bits(shift_round(product, 30 + self.shift) as i64)
        };
        (part(direction.0), part(direction.1))
    }
}

/// Everything `[` saves: 32 bytes, the step's two parts apart (as a `Step` it would be
/// padded to 16 bytes), and the heading in a byte (`Angle n` has n ≤ 64).
#[derive(Debug, Clone, Copy)]
struct State {
    position: TurtlePoint,
    /// The step's mantissa and shift (see [`Step`]).
    step: Real,
    step_shift: u8,
    /// The heading for `Angle n`, in divisions (0..n).
    heading: u8,
    /// The free heading (`\`, `/`, `D`, `M`; and every turn for a free angle).
    free: BinaryAngle,
    color: u8,
    reversed: bool,
}

impl State {
    fn step(&self) -> Step {
        Step {
            mantissa: self.step,
            shift: u32::from(self.step_shift),
        }
    }

    fn set_step(&mut self, step: Step) {
        self.step = step.mantissa;
        // At most `MAX_STEP_SHIFT`.
        self.step_shift = step.shift as u8;
    }
}

/// The turtle: a state and a stack of saved states (`STACK` deep).
#[derive(Debug, Clone)]
pub(crate) struct Turtle<'g, const STACK: usize> {
    headings: &'g Headings,
    dialect: Dialect,
    state: State,
    stack: Vec<State, STACK>,
    max_stack: usize,
    /// Steps below this (but 0) are [`WalkError::StepUnderflow`] after `@` (none in a walk
    /// in pixels, where this is 0).
    min_step: Real,
    /// Step vectors of the last few headings, for the current step.
    steps: StepCache,
    /// `@` commands carried out (for the fit's bound on rounding, see `LSystem::fit`).
    scalings: u64,
}

impl<'g, const STACK: usize> Turtle<'g, STACK> {
    /// A turtle at `start`. A walk in turtle units refuses a first step below
    /// [`MIN_STEP`] ([`WalkError::StepTooFine`]); one in pixels (`in_pixels`) takes any.
    pub(crate) fn new(
        headings: &'g Headings,
        dialect: Dialect,
        start: Start,
        in_pixels: bool,
    ) -> Result<Self, Error> {
        let step = Step::new(start.step, start.step_shift);
        if !in_pixels && step.too_fine() {
            return Err(Error::Walk(WalkError::StepTooFine));
        }
        let mut turtle = Self {
            headings,
            dialect,
            state: State {
                position: start.position,
                step: step.mantissa,
                step_shift: step.shift as u8,
                heading: 0,
                free: BinaryAngle::default(),
                color: 0,
                reversed: false,
            },
            stack: Vec::new(),
            max_stack: 0,
            min_step: if in_pixels { Real::ZERO } else { MIN_STEP },
            steps: StepCache::EMPTY,
            scalings: 0,
        };
        let left = start.turns >= 0;
        for _ in 0..start.turns.unsigned_abs() % 65_536 {
            turtle.turn(left);
        }
        Ok(turtle)
    }

    /// One turn by the system's angle, counter-clockwise if `left`. Headings wrap by a
    /// comparison, not `%`: Cortex-M0 has no divide instruction.
    #[inline(always)]
    fn turn(&mut self, left: bool) {
        let n = self.headings.divisions();
        let state = &mut self.state;
        if n == 0 {
            let delta = self.headings.free_turn().0;
            state.free.0 = if left {
                state.free.0.wrapping_add(delta)
            } else {
                state.free.0.wrapping_sub(delta)
            };
        } else if left {
            state.heading = if u16::from(state.heading) + 1 >= n {
                0
            } else {
                state.heading + 1
            };
        } else {
            state.heading = if state.heading == 0 {
                // n ≤ 64: it fits.
                (n - 1) as u8
            } else {
                state.heading - 1
            };
        }
    }

    /// Moves one step along the main heading and returns the segment it covered.
    #[inline(always)]
    fn advance_main(&mut self) -> Result<Segment, Error> {
        let vector = self.main_vector();
        self.advance_along(vector)
    }

    /// One step along the main heading: kept per heading while the step stays. For
    /// `Angle n`, headings k and n - k share a slot (their vectors are mirror images
    /// exactly: the table's directions are, and [`Real::mul_q30`] rounds the magnitude).
    #[inline(always)]
    fn main_vector(&mut self) -> (Real, Real) {
        let n = self.headings.divisions();
        let step = self.state.step();
        if n == 0 {
            let angle = self.state.free;
            let shift = self.headings.cycle_shift();
            // Keys are 16 bits: free headings keyed by their index among the multiples of
            // 2^shift, when those are few enough; any others are computed each time.
            let Ok(key) = u16::try_from(angle.0.checked_shr(shift).unwrap_or(0)) else {
                return step.vector(angle.cos_sin());
            };
            return match self.steps.get(key) {
                Some(vector) => vector,
                None => {
                    let vector = step.vector(angle.cos_sin());
                    self.steps.put(key, vector);
                    vector
                }
            };
        }
        // The look-up and fill are written out in both arms: a shared closure costs more
        // on Cortex-M3 and M4.
        let heading = u16::from(self.state.heading);
        let mirrored = heading > n / 2;
        let k = if mirrored { n - heading } else { heading };
        let (dx, dy) = match self.steps.get(k) {
            Some(vector) => vector,
            None => {
                let vector = step.vector(self.headings.cos_sin(k));
                self.steps.put(k, vector);
                vector
            }
        };
        (
            dx,
            if mirrored {
                Real::from_bits(dy.to_bits().wrapping_neg())
            } else {
                dy
            },
        )
    }

    /// Moves `step` along `direction` and returns the segment it covered.
    fn advance_by(&mut self, step: Step, direction: (i32, i32)) -> Result<Segment, Error> {
        self.advance_along(step.vector(direction))
    }

    /// Moves by `(dx, dy)` and returns the segment it covered.
    #[inline(always)]
    fn advance_along(&mut self, (dx, dy): (Real, Real)) -> Result<Segment, Error> {
        let start = self.state.position;
        let end = TurtlePoint {
            x: start
                .x
                .checked_add(dx)
                .ok_or(Error::Walk(WalkError::Overflow))?,
            y: start
                .y
                .checked_add(dy)
                .ok_or(Error::Walk(WalkError::Overflow))?,
        };
        self.state.position = end;
        Ok(Segment {
            start,
            end,
            color: self.state.color,
        })
    }

    fn main_direction(&self) -> (i32, i32) {
        if self.headings.divisions() == 0 {
            self.state.free.cos_sin()
        } else {
            self.headings.cos_sin(u16::from(self.state.heading))
        }
    }

    /// Carries out one command; returns the segment if it drew one. Inlined into the walk
    /// loops: a call per symbol costs more than most commands.
    #[inline(always)]
    pub(crate) fn execute(&mut self, command: Command) -> Result<Option<Segment>, Error> {
        let state = &mut self.state;
        match command {
            Command::Draw => return self.advance_main().map(Some),
            Command::DrawFree => {
                return self
                    .advance_by(self.state.step(), self.state.free.cos_sin())
                    .map(Some)
            }
            Command::DrawBy(length) | Command::MoveBy(length) => {
                let step = state
                    .step()
                    .times(length)
                    .ok_or(Error::Walk(WalkError::Overflow))?;
                let segment = self.advance_by(step, self.main_direction())?;
                return Ok(matches!(command, Command::DrawBy(_)).then_some(segment));
            }
            Command::Move => {
                self.advance_main()?;
            }
            Command::MoveFree => {
                self.advance_by(self.state.step(), self.state.free.cos_sin())?;
            }
            Command::Left => {
                let left = !state.reversed;
                self.turn(left);
            }
            Command::Right => {
                let left = state.reversed;
                self.turn(left);
            }
            Command::Around => {
                let n = self.headings.divisions();
                if n == 0 {
                    state.free.0 = state.free.0.wrapping_add(1 << 31);
                } else {
                    // Half a turn: n - n/2 divisions (headings are below n ≤ 64).
                    let turned = u16::from(state.heading) + (n - n / 2);
                    state.heading = if turned >= n { turned - n } else { turned } as u8;
                }
            }
            Command::Reverse => state.reversed = !state.reversed,
            Command::FreeLeft(turn) | Command::FreeRight(turn) => {
                let delta = turn.0;
                let left = matches!(command, Command::FreeLeft(_)) != state.reversed;
                state.free.0 = if left {
                    state.free.0.wrapping_add(delta)
                } else {
                    state.free.0.wrapping_sub(delta)
                };
            }
            Command::Scale(factor) => self.scale(factor)?,
            Command::SetColor(color) => state.color = color,
            Command::RaiseColor(by) => state.color = state.color.wrapping_add(by),
            Command::LowerColor(by) => state.color = state.color.wrapping_sub(by),
            Command::Push => {
                // Field by field: copied whole, the state went through a library memmove.
                let saved = State { ..*state };
                self.stack
                    .push(saved)
                    .map_err(|_| Error::Walk(WalkError::StackTooDeep { capacity: STACK }))?;
                self.max_stack = self.max_stack.max(self.stack.len());
            }
            Command::Pop => {
                let saved = self
                    .stack
                    .pop()
                    .ok_or(Error::Read(ReadError::UnbalancedBracket {
                        at: crate::error::Location::default(),
                    }))?;
                // Fractint's `]` restores everything but the colour; ABOP's restores all.
                let color = state.color;
                if saved.step != state.step || saved.step_shift != state.step_shift {
                    self.steps.clear();
                }
                *state = saved;
                if self.dialect == Dialect::Fractint {
                    state.color = color;
                }
            }
            Command::Nothing => {}
        }
        Ok(None)
    }
}

/// Headings whose step vectors a turtle keeps (a few: the walk's state stays under 1 KiB).
const STEP_SLOTS: usize = 4;

/// Step vectors for the current step, direct-mapped by heading: a snowflake's turns between
/// steps, or a plant's branches, come back to the same few headings, so most steps reuse
/// a vector instead of computing two 64-bit products (in software on Cortex-M0).
#[derive(Debug, Clone, Copy)]
struct StepCache {
    vectors: [(Real, Real); STEP_SLOTS],
    /// The heading each slot holds: the division (of the half turn's mirror images, for
    /// `Angle n`), or a free heading's index.
    keys: [u16; STEP_SLOTS],
    /// Which slots hold a vector, one bit each.
    filled: u8,
}

impl StepCache {
    const EMPTY: Self = Self {
        vectors: [(Real::ZERO, Real::ZERO); STEP_SLOTS],
        keys: [0; STEP_SLOTS],
        filled: 0,
    };

    /// Forgets every vector (the step changed).
    #[inline(always)]
    fn clear(&mut self) {
        self.filled = 0;
    }

    #[inline(always)]
    fn get(&self, key: u16) -> Option<(Real, Real)> {
        let slot = usize::from(key) % STEP_SLOTS;
        let held = self.filled >> slot & 1 != 0 && self.keys.get(slot) == Some(&key);
        held.then(|| self.vectors.get(slot).copied()).flatten()
    }

    #[inline(always)]
    fn put(&mut self, key: u16, vector: (Real, Real)) {
        let slot = usize::from(key) % STEP_SLOTS;
        if let (Some(k), Some(v)) = (self.keys.get_mut(slot), self.vectors.get_mut(slot)) {
            (*k, *v) = (key, vector);
            self.filled |= 1 << slot;
        }
    }
}

/// `step` along `(cos, sin)` (Q30): the vector one step moves by. Without a long multiply
/// (Cortex-M0, where the products are library calls) a step of 1, as the fit's sizing walk
/// in turtle units has, is exact without them: Q30 to Q32 is a shift (on M3 and M4F the
/// test would cost as much as it saves).
#[inline(always)]
fn scaled(step: Real, (cos, sin): (i32, i32)) -> (Real, Real) {
    #[cfg(tinyfractal_no_long_multiply)]
    if step == Real::ONE {
        let unit = |v: i32| Real::from_bits(i64::from(v) << 2);
        return (unit(cos), unit(sin));
    }
    (step.mul_q30(cos), step.mul_q30(sin))
}

impl<const STACK: usize> Turtle<'_, STACK> {
    /// `@`: the step times `factor`. Out of line (see [`Step::times`]).
    #[inline(never)]
    fn scale(&mut self, factor: Real) -> Result<(), Error> {
        self.steps.clear();
        self.scalings += 1;
        let step = self
            .state
            .step()
            .times(factor)
            .ok_or(Error::Walk(WalkError::Overflow))?;
        self.state.set_step(step);
        // A step of exactly 0 is Fractint's `@` without a number: points.
        if step.below(self.min_step) {
            return Err(Error::Walk(WalkError::StepUnderflow));
        }
        Ok(())
    }

    /// Where the turtle is.
    pub(super) fn position(&self) -> TurtlePoint {
        self.state.position
    }

    /// The colour index the turtle draws in.
    pub(super) fn color(&self) -> u8 {
        self.state.color
    }

    /// The heading and sense of `!` the turtle has now, as a table looks them up: the
    /// division, or the free heading's index in its cycle.
    pub(super) fn table_heading(&self) -> (u16, bool) {
        let heading = if self.headings.divisions() > 0 {
            u16::from(self.state.heading)
        } else {
            let shift = self.headings.cycle().map_or(31, |cycle| cycle.shift);
            u16::try_from(self.state.free.0 >> shift).unwrap_or(u16::MAX)
        };
        (heading, self.state.reversed)
    }

    /// How many `@` commands the turtle has carried out.
    pub(super) fn scalings(&self) -> u64 {
        self.scalings
    }

    /// The deepest the turtle stack got.
    pub(super) fn max_stack(&self) -> usize {
        self.max_stack
    }

    /// The turtle moved past an expansion summarised by `cell`; `None` on overflow.
    pub(super) fn pass(&mut self, cell: &Summary) -> Option<()> {
        let state = &mut self.state;
        state.position = TurtlePoint {
            x: state.position.x.checked_add(cell.displacement.0)?,
            y: state.position.y.checked_add(cell.displacement.1)?,
        };
        if self.headings.divisions() > 0 {
            // A division of n ≤ 64.
            state.heading = cell.heading as u8;
        } else {
            let shift = self.headings.cycle()?.shift;
            state.free = BinaryAngle(u32::from(cell.heading) << shift);
        }
        state.reversed = cell.reversed;
        state.color = cell.color.apply(state.color);
        let inside = usize::try_from(cell.nesting).unwrap_or(usize::MAX);
        self.max_stack = self.max_stack.max(self.stack.len().saturating_add(inside));
        Some(())
    }
}
