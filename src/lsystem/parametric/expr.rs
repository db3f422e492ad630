//! Arithmetic and logic over module parameters, compiled once into postfix code and
//! evaluated in fixed point with a bounded stack: `x*2`, `x+y`, `y <= 3 && !(x == 0)`,
//! `l/1.456`, `2^n`, `sqrt(x)`, `sin(a)`, `cos(a)`, `tan(a)` (degrees).
//!
//! Precedence, loosest first: `||`, `&&`, comparisons (`< <= > >= == !=`), `+ -`, `* /`,
//! unary `- !`, `^` (right-associative), then numbers, names and parentheses. Truth is 1,
//! falsehood 0; a condition holds when its value is not 0.

use heapless::Vec;

use crate::math::trig::BinaryAngle;
use crate::math::Real;

/// Most instructions of all a system's expressions together.
pub const MAX_CODE: usize = 512;

/// Deepest evaluation stack (nesting of an expression).
pub const MAX_EVAL_DEPTH: usize = 16;

/// One postfix instruction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Instr {
    Const(Real),
    /// The i-th parameter of the production's predecessor.
    Param(u8),
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Neg,
    Not,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Sqrt,
    /// Sine, cosine and tangent of degrees.
    Sin,
    Cos,
    Tan,
    /// `env(k)`: the environment's answer to query `k` where the walk is.
    Env,
}

/// What answers `env(k)` during a walk: the environment, asked about the turtle where the
/// module is expanded.
pub(crate) type Query<'q> = Option<&'q dyn Fn(Real) -> Real>;

/// Where an expression's code is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Code {
    pub(crate) start: u16,
    pub(crate) end: u16,
}

/// Why an expression cannot be read, and where in its text (a byte offset).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SyntaxError {
    /// Something that is not part of an expression.
    Unexpected(usize),
    /// A name that is neither a parameter nor a constant.
    UnknownName(usize),
    /// More code than [`MAX_CODE`].
    TooLong(usize),
}

/// Why an expression cannot be evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EvalError {
    DivisionByZero,
    /// A result beyond the fixed-point range, a power that is not a whole number, or a
    /// square root of a negative number.
    OutOfRange,
    /// Nested deeper than [`MAX_EVAL_DEPTH`].
    TooDeep,
    /// `env(k)` with no environment to answer.
    NoEnvironment,
}

/// Names an expression may use: the predecessor's parameters (by position) and the
/// system's constants.
pub(crate) struct Names<'n, 'a> {
    pub(crate) params: &'n [&'a str],
    pub(crate) constants: &'n [(&'a str, Real)],
}

/// Compiles `text` onto `code`.
pub(crate) fn compile<const N: usize>(
    text: &str,
    names: &Names<'_, '_>,
    code: &mut Vec<Instr, N>,
) -> Result<Code, SyntaxError> {
    let start = code.len();
    let mut parser = Parser {
        bytes: text.as_bytes(),
        at: 0,
        names,
        code,
    };
    parser.or()?;
    parser.skip_space();
    if parser.at < parser.bytes.len() {
        return Err(SyntaxError::Unexpected(parser.at));
    }
    let position = |index: usize| u16::try_from(index).unwrap_or(u16::MAX);
    Ok(Code {
        start: position(start),
        end: position(parser.code.len()),
    })
}

struct Parser<'t, 'n, 'c, 'a, const N: usize> {
    bytes: &'t [u8],
    at: usize,
    names: &'n Names<'n, 'a>,
    code: &'c mut Vec<Instr, N>,
}

impl<const N: usize> Parser<'_, '_, '_, '_, N> {
    fn skip_space(&mut self) {
        while self.bytes.get(self.at).is_some_and(u8::is_ascii_whitespace) {
            self.at += 1;
        }
    }

    /// Takes `token` if it comes next.
    fn eat(&mut self, token: &str) -> bool {
        self.skip_space();
        let matches = self
            .bytes
            .get(self.at..self.at + token.len())
            .is_some_and(|next| next == token.as_bytes());
        if matches {
            self.at += token.len();
        }
        matches
    }

    fn emit(&mut self, instr: Instr) -> Result<(), SyntaxError> {
        self.code
            .push(instr)
            .map_err(|_| SyntaxError::TooLong(self.at))
    }

    fn or(&mut self) -> Result<(), SyntaxError> {
        self.and()?;
        while self.eat("||") {
            self.and()?;
            self.emit(Instr::Or)?;
        }
        Ok(())
    }

    fn and(&mut self) -> Result<(), SyntaxError> {
        self.comparison()?;
        while self.eat("&&") {
            self.comparison()?;
            self.emit(Instr::And)?;
        }
        Ok(())
    }

    fn comparison(&mut self) -> Result<(), SyntaxError> {
        self.sum()?;
        // Two-character operators first.
        for (token, instr) in [
            ("<=", Instr::Le),
            (">=", Instr::Ge),
            ("==", Instr::Eq),
            ("!=", Instr::Ne),
            ("<", Instr::Lt),
            (">", Instr::Gt),
        ] {
            if self.eat(token) {
                self.sum()?;
                return self.emit(instr);
            }
        }
        Ok(())
    }

    fn sum(&mut self) -> Result<(), SyntaxError> {
        self.product()?;
        loop {
            if self.eat("+") {
                self.product()?;
                self.emit(Instr::Add)?;
            } else if self.eat("-") {
                self.product()?;
                self.emit(Instr::Sub)?;
            } else {
                return Ok(());
            }
        }
    }

    fn product(&mut self) -> Result<(), SyntaxError> {
        self.unary()?;
        loop {
            if self.eat("*") {
                self.unary()?;
                self.emit(Instr::Mul)?;
            } else if self.eat("/") {
                self.unary()?;
                self.emit(Instr::Div)?;
            } else {
                return Ok(());
            }
        }
    }

    fn unary(&mut self) -> Result<(), SyntaxError> {
        if self.eat("-") {
            self.unary()?;
            self.emit(Instr::Neg)
        } else if self.eat("!") {
            if self.bytes.get(self.at) == Some(&b'=') {
                return Err(SyntaxError::Unexpected(self.at));
            }
            self.unary()?;
            self.emit(Instr::Not)
        } else {
            self.power()
        }
    }

    fn power(&mut self) -> Result<(), SyntaxError> {
        self.atom()?;
        if self.eat("^") {
            // Right-associative, and binds the sign of its exponent: 2^-1.
            self.unary()?;
            self.emit(Instr::Pow)?;
        }
        Ok(())
    }

    fn atom(&mut self) -> Result<(), SyntaxError> {
        self.skip_space();
        let start = self.at;
        if self.eat("(") {
            self.or()?;
            return if self.eat(")") {
                Ok(())
            } else {
                Err(SyntaxError::Unexpected(self.at))
            };
        }
        let byte = self.bytes.get(start).copied().unwrap_or(b' ');
        if byte.is_ascii_digit() || byte == b'.' {
            let length = self
                .bytes
                .get(start..)
                .unwrap_or_default()
                .iter()
                .take_while(|b| b.is_ascii_digit() || **b == b'.')
                .count();
            let value =
                core::str::from_utf8(self.bytes.get(start..start + length).unwrap_or_default())
                    .ok()
                    .and_then(Real::parse_decimal)
                    .ok_or(SyntaxError::Unexpected(start))?;
            self.at = start + length;
            return self.emit(Instr::Const(value));
        }
        if byte.is_ascii_alphabetic() || byte == b'_' {
            let length = self
                .bytes
                .get(start..)
                .unwrap_or_default()
                .iter()
                .take_while(|b| b.is_ascii_alphanumeric() || **b == b'_')
                .count();
            let name =
                core::str::from_utf8(self.bytes.get(start..start + length).unwrap_or_default())
                    .unwrap_or_default();
            self.at = start + length;
            let function = match name {
                "sqrt" => Some(Instr::Sqrt),
                "sin" => Some(Instr::Sin),
                "cos" => Some(Instr::Cos),
                "tan" => Some(Instr::Tan),
                "env" => Some(Instr::Env),
                _ => None,
            };
            if let Some(function) = function.filter(|_| self.eat("(")) {
                self.or()?;
                if !self.eat(")") {
                    return Err(SyntaxError::Unexpected(self.at));
                }
                return self.emit(function);
            }
            if let Some(index) = self.names.params.iter().position(|&p| p == name) {
                return self.emit(Instr::Param(u8::try_from(index).unwrap_or(u8::MAX)));
            }
            if let Some(&(_, value)) = self.names.constants.iter().find(|(n, _)| *n == name) {
                return self.emit(Instr::Const(value));
            }
            return Err(SyntaxError::UnknownName(start));
        }
        Err(SyntaxError::Unexpected(start))
    }
}

fn truth(value: bool) -> Real {
    if value {
        Real::ONE
    } else {
        Real::ZERO
    }
}

/// `base` to a whole power of up to ±64.
fn power(base: Real, exponent: Real) -> Result<Real, EvalError> {
    let whole = exponent.to_bits() >> Real::FRAC_BITS;
    if exponent.to_bits() & ((1 << Real::FRAC_BITS) - 1) != 0 || !(-64..=64).contains(&whole) {
        return Err(EvalError::OutOfRange);
    }
    let mut result = Real::ONE;
    for _ in 0..whole.unsigned_abs() {
        result = result.checked_mul(base).ok_or(EvalError::OutOfRange)?;
    }
    if whole < 0 {
        result = Real::ONE
            .checked_div(result)
            .ok_or(EvalError::DivisionByZero)?;
    }
    Ok(result)
}

/// Evaluates `code` with the bound parameters `params`; `query` answers `env(k)`.
pub(crate) fn evaluate(code: &[Instr], params: &[Real], query: Query) -> Result<Real, EvalError> {
    // The common shapes first, without the stack: a constant or a parameter, and one sum,
    // difference or product of two of them (`l*r2`); the same values as the stack's.
    let leaf = |instr: Instr| match instr {
        Instr::Const(value) => Some(value),
        Instr::Param(index) => Some(
            params
                .get(usize::from(index))
                .copied()
                .unwrap_or(Real::ZERO),
        ),
        _ => None,
    };
    match *code {
        [only] => {
            if let Some(value) = leaf(only) {
                return Ok(value);
            }
        }
        [a, b, op @ (Instr::Add | Instr::Sub | Instr::Mul)] => {
            if let (Some(a), Some(b)) = (leaf(a), leaf(b)) {
                let value = match op {
                    Instr::Add => a.checked_add(b),
                    Instr::Sub => a.checked_sub(b),
                    _ => a.checked_mul(b),
                };
                return value.ok_or(EvalError::OutOfRange);
            }
        }
        _ => {}
    }
    evaluate_on_stack(code, params, query)
}

/// [`evaluate`] by the stack machine: any expression.
fn evaluate_on_stack(code: &[Instr], params: &[Real], query: Query) -> Result<Real, EvalError> {
    let mut stack: Vec<Real, MAX_EVAL_DEPTH> = Vec::new();
    for &instr in code {
        let value = match instr {
            Instr::Const(value) => value,
            Instr::Param(index) => params
                .get(usize::from(index))
                .copied()
                .unwrap_or(Real::ZERO),
            Instr::Neg => Real::ZERO
                .checked_sub(stack.pop().unwrap_or(Real::ZERO))
                .ok_or(EvalError::OutOfRange)?,
            Instr::Not => truth(stack.pop().unwrap_or(Real::ZERO) == Real::ZERO),
            Instr::Sqrt => stack
                .pop()
                .unwrap_or(Real::ZERO)
                .checked_sqrt()
                .ok_or(EvalError::OutOfRange)?,
            Instr::Env => {
                let query = query.ok_or(EvalError::NoEnvironment)?;
                query(stack.pop().unwrap_or(Real::ZERO))
            }
            Instr::Sin | Instr::Cos | Instr::Tan => {
                let degrees = stack.pop().unwrap_or(Real::ZERO);
                let (cos, sin) = BinaryAngle::from_degrees_bits(degrees.to_bits()).cos_sin();
                // Q30 to Q32.
                let real = |q30: i32| Real::from_bits(i64::from(q30) << 2);
                match instr {
                    Instr::Sin => real(sin),
                    Instr::Cos => real(cos),
                    _ if cos == 0 => return Err(EvalError::DivisionByZero),
                    _ => real(sin)
                        .checked_div(real(cos))
                        .ok_or(EvalError::OutOfRange)?,
                }
            }
            binary => {
                let b = stack.pop().unwrap_or(Real::ZERO);
                let a = stack.pop().unwrap_or(Real::ZERO);
                let range = EvalError::OutOfRange;
                match binary {
                    Instr::Add => a.checked_add(b).ok_or(range)?,
                    Instr::Sub => a.checked_sub(b).ok_or(range)?,
                    Instr::Mul => a.checked_mul(b).ok_or(range)?,
                    Instr::Div if b == Real::ZERO => return Err(EvalError::DivisionByZero),
                    Instr::Div => a.checked_div(b).ok_or(range)?,
                    Instr::Pow => power(a, b)?,
                    Instr::Lt => truth(a < b),
                    Instr::Le => truth(a <= b),
                    Instr::Gt => truth(a > b),
                    Instr::Ge => truth(a >= b),
                    Instr::Eq => truth(a == b),
                    Instr::Ne => truth(a != b),
                    Instr::And => truth(a != Real::ZERO && b != Real::ZERO),
                    _ => truth(a != Real::ZERO || b != Real::ZERO),
                }
            }
        };
        stack.push(value).map_err(|_| EvalError::TooDeep)?;
    }
    Ok(stack.pop().unwrap_or(Real::ZERO))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shapes evaluated without the stack give the stack's values and errors: leaves
    /// alone, and sums, differences and products of two, near the range's ends too.
    #[test]
    fn shortcuts_are_the_stack_machines() {
        let values = [
            Real::ZERO,
            Real::ONE,
            Real::from_bits(-0x1234_5678_9ABC),
            Real::from_bits(i64::MAX),
            Real::from_bits(i64::MIN + 1),
            Real::from_bits(3 << 40),
        ];
        let params = [values[2], values[3], values[5]];
        let leaves = values
            .iter()
            .map(|&v| Instr::Const(v))
            .chain((0..4).map(Instr::Param));
        let leaves: Vec<Instr, 16> = leaves.collect();
        for &a in &leaves {
            assert_eq!(
                evaluate(&[a], &params, None),
                evaluate_on_stack(&[a], &params, None)
            );
            for &b in &leaves {
                for op in [Instr::Add, Instr::Sub, Instr::Mul, Instr::Div] {
                    let code = [a, b, op];
                    assert_eq!(
                        evaluate(&code, &params, None),
                        evaluate_on_stack(&code, &params, None),
                        "{code:?}"
                    );
                }
            }
        }
    }
}
