//! An attractor with its parameters, start and time step, and its orbit: the points after
//! a skipped transient, one step apart.

use super::fixed::{to_fixed, to_real};
use super::kind::{Kind, Method};
use super::step::{State, Stepper, WithStep};
use crate::error::{Error, ParameterError, WalkError};
use crate::math::Real;

/// An attractor ready to iterate: its kind, parameters, start, and (for a flow) time step
/// and method. [`Attractor::new`] takes the kind's defaults; each `with_` checks its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Attractor {
    kind: Kind,
    parameters: [Real; 4],
    start: [Real; 3],
    time_step: Real,
    method: Method,
    stepper: Stepper,
    first: State,
}

impl Attractor {
    /// `kind` with its default parameters, start and time step, integrated by RK4.
    pub fn new(kind: Kind) -> Self {
        let parameters = kind.default_parameters();
        let start = kind.default_start();
        let time_step = kind.default_time_step().unwrap_or(Real::ZERO);
        // The defaults are within range (tested): the fallbacks are never taken.
        let stepper = Stepper::new(kind, parameters, time_step, Method::Rk4)
            .unwrap_or(Stepper::Martin { a: 0 });
        let first = Self::state_of(kind, start).unwrap_or([0; 3]);
        Self {
            kind,
            parameters,
            start,
            time_step,
            method: Method::Rk4,
            stepper,
            first,
        }
    }

    fn state_of(kind: Kind, start: [Real; 3]) -> Result<State, Error> {
        let bits = kind.fraction_bits();
        let one = |value: Real| {
            to_fixed(value, bits).ok_or(Error::Parameter(
                ParameterError::AttractorValueOutOfRange {
                    value,
                    max: kind.range(),
                },
            ))
        };
        let z = if kind.dimensions() == 3 {
            one(start[2])?
        } else {
            0
        };
        Ok([one(start[0])?, one(start[1])?, z])
    }

    fn rebuilt(mut self) -> Result<Self, Error> {
        self.stepper = Stepper::new(self.kind, self.parameters, self.time_step, self.method)?;
        self.first = Self::state_of(self.kind, self.start)?;
        Ok(self)
    }

    /// Other parameters: exactly [`Kind::parameter_count`] of them (a, b, c, d in order),
    /// each within the kind's range.
    pub fn with_parameters(mut self, parameters: &[Real]) -> Result<Self, Error> {
        let expected = self.kind.parameter_count();
        if parameters.len() != expected {
            return Err(Error::Parameter(ParameterError::ParameterCount {
                given: parameters.len(),
                expected,
            }));
        }
        self.parameters = [Real::ZERO; 4];
        for (slot, value) in self.parameters.iter_mut().zip(parameters) {
            *slot = *value;
        }
        self.rebuilt()
    }

    /// Another start: x, y (and z for a 3D kind; ignored for a 2D one).
    pub fn with_start(mut self, start: [Real; 3]) -> Result<Self, Error> {
        self.start = start;
        self.rebuilt()
    }

    /// A flow's time step, in (0, 1]; a map has none and ignores it.
    pub fn with_time_step(mut self, time_step: Real) -> Result<Self, Error> {
        if !self.kind.is_flow() {
            return Ok(self);
        }
        if time_step <= Real::ZERO || time_step > Real::ONE {
            return Err(Error::Parameter(ParameterError::TimeStepOutOfRange {
                dt: time_step,
            }));
        }
        self.time_step = time_step;
        self.rebuilt()
    }

    /// How a flow is integrated (a map ignores it).
    pub fn with_method(mut self, method: Method) -> Result<Self, Error> {
        self.method = method;
        self.rebuilt()
    }

    /// The kind.
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// The parameters (a, b, c, d; unused ones 0).
    pub fn parameters(&self) -> [Real; 4] {
        self.parameters
    }

    /// The start.
    pub fn start(&self) -> [Real; 3] {
        self.start
    }

    /// A flow's time step (0 for a map).
    pub fn time_step(&self) -> Real {
        self.time_step
    }

    /// The point after `point` (exact in the kind's fixed point: `point` is rounded to it
    /// first), or the error of an orbit leaving the range.
    pub fn step(&self, point: [Real; 3]) -> Result<[Real; 3], Error> {
        let state = Self::state_of(self.kind, point)?;
        let next = self.stepper.step(state).ok_or(self.escaped(1))?;
        Ok(self.real(next))
    }

    /// The orbit: `count` points, the first after `skip` steps from the start (`skip` 0:
    /// the start itself).
    pub fn orbit(&self, skip: u64, count: u64) -> Orbit {
        Orbit {
            attractor: *self,
            state: self.first,
            skip,
            left: count,
            index: 0,
            started: false,
            failed: false,
        }
    }

    /// Where the orbit of `count` points after `skip` steps starts: the transient taken
    /// now, once, for [`Attractor::orbit_from`] to start there again (an orbit of no
    /// points takes no step, as when it is run).
    pub(crate) fn settled(&self, skip: u64, count: u64) -> Result<Settled, Error> {
        let mut state = self.first;
        if count > 0 {
            for index in 1..=skip {
                state = self
                    .stepper
                    .step(state)
                    .ok_or_else(|| self.escaped(index))?;
            }
        }
        Ok(Settled::new(state, skip))
    }

    /// The orbit of `count` points from `settled` (its first point).
    pub(crate) fn orbit_from(&self, settled: Settled, count: u64) -> Orbit {
        Orbit {
            attractor: *self,
            state: settled.state,
            skip: 0,
            left: count,
            index: settled.index,
            started: false,
            failed: false,
        }
    }

    pub(crate) fn real(&self, state: State) -> [Real; 3] {
        let bits = self.kind.fraction_bits();
        state.map(|value| to_real(value, bits))
    }

    pub(crate) fn escaped(&self, step: u64) -> Error {
        Error::Walk(WalkError::OrbitEscaped {
            step,
            range: self.kind.range(),
        })
    }
}

/// An orbit's first point past its transient, and the steps taken to it: where a drawing
/// fitted once starts again.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Settled {
    state: State,
    index: u64,
}

impl Settled {
    /// The orbit's point `state`, `index` steps from its start.
    pub(crate) fn new(state: State, index: u64) -> Self {
        Self { state, index }
    }
}

/// The points of an orbit, in the attractor's units; yields an `Err` once if the orbit
/// leaves the kind's range, then ends.
#[derive(Debug, Clone)]
pub struct Orbit {
    attractor: Attractor,
    state: State,
    skip: u64,
    left: u64,
    index: u64,
    started: bool,
    failed: bool,
}

impl Orbit {
    /// The next state in the kind's fixed point (what the drawings place). A step is
    /// taken only when its point is asked for.
    #[inline]
    pub(crate) fn next_state(&mut self) -> Option<Result<State, Error>> {
        if self.failed || self.left == 0 {
            return None;
        }
        while self.skip > 0 {
            self.skip -= 1;
            if let Err(error) = self.advance() {
                return Some(Err(error));
            }
        }
        if self.started {
            if let Err(error) = self.advance() {
                return Some(Err(error));
            }
        }
        self.started = true;
        self.left -= 1;
        Some(Ok(self.state))
    }

    /// Runs the rest of the orbit, handing `visit` each point's picture-plane coordinates
    /// seen from the front (x and y, or x and z for a kind of three dimensions, chosen
    /// once a run) and its state, in order: the drawings' loop, with the kind's step
    /// inlined and no `Result` a point. Ends at the first state out of range with its
    /// error, the points before it visited.
    #[inline]
    pub(crate) fn run(&mut self, visit: impl FnMut([i32; 2], State)) -> Result<(), Error> {
        let stepper = self.attractor.stepper;
        stepper.with_step(Run { orbit: self, visit })
    }

    /// Points not yet given.
    pub(crate) fn remaining(&self) -> u64 {
        if self.failed {
            0
        } else {
            self.left
        }
    }

    /// The orbit's error at `steps` steps past the last state kept.
    #[cold]
    fn fail(&mut self, steps: u64) -> Error {
        self.failed = true;
        self.attractor.escaped(self.index + steps)
    }

    #[inline]
    fn advance(&mut self) -> Result<(), Error> {
        self.index += 1;
        match self.attractor.stepper.step(self.state) {
            Some(next) => {
                self.state = next;
                Ok(())
            }
            None => {
                self.failed = true;
                Err(self.attractor.escaped(self.index))
            }
        }
    }

    /// The attractor it follows.
    pub fn attractor(&self) -> &Attractor {
        &self.attractor
    }
}

impl Iterator for Orbit {
    type Item = Result<[Real; 3], Error>;

    fn next(&mut self) -> Option<Self::Item> {
        let state = self.next_state()?;
        Some(state.map(|state| self.attractor.real(state)))
    }
}

/// [`Orbit::run`] with the kind's step in hand.
struct Run<'o, V> {
    orbit: &'o mut Orbit,
    visit: V,
}

/// The picture plane seen from the front: x and y, or x and z (z up) for a kind of three
/// dimensions.
#[inline(always)]
pub(super) fn plane<const THREE: bool>([x, y, z]: State) -> [i32; 2] {
    [x, if THREE { z } else { y }]
}

impl<V: FnMut([i32; 2], State)> WithStep for Run<'_, V> {
    type Output = Result<(), Error>;
    const MANY_STEPS: bool = true;

    #[inline(always)]
    fn with<const THREE: bool>(
        mut self,
        step: impl Fn(State) -> Option<State>,
    ) -> Result<(), Error> {
        let orbit = self.orbit;
        if orbit.failed || orbit.left == 0 {
            return Ok(());
        }
        let mut state = orbit.state;
        // The transient, and the step from the last point given to the next.
        let pending = orbit.skip + u64::from(orbit.started);
        for done in 0..pending {
            match step(state) {
                Some(next) => state = next,
                None => return Err(orbit.fail(done + 1)),
            }
        }
        let count = orbit.left;
        (self.visit)(plane::<THREE>(state), state);
        let mut visited = 1;
        // The rest in blocks a 32-bit counter covers: one register for the loop's count.
        while visited < count {
            let block = u32::try_from(count - visited).unwrap_or(u32::MAX);
            // Counted down to 0: the count is the loop's only register.
            let mut left = block;
            while left > 0 {
                match step(state) {
                    Some(next) => state = next,
                    None => {
                        orbit.left = 0;
                        // The steps taken, from what was left: the loop keeps `left` alone.
                        let end = pending + visited + u64::from(block);
                        return Err(orbit.fail(end - u64::from(left)));
                    }
                }
                (self.visit)(plane::<THREE>(state), state);
                left -= 1;
            }
            visited += u64::from(block);
        }
        orbit.state = state;
        orbit.index += pending + (count - 1);
        (orbit.skip, orbit.left, orbit.started) = (0, 0, true);
        Ok(())
    }
}
