//! The lecture's matrix notation: the Koch curve written with S, T, R and D draws the same
//! 4ⁿ segments as `F → F+F--F+F` scaled by 3⁻ⁿ, against an f64 model written here.

use tinyfractal::{lsystem::Segments3, LsysFile};

/// The Koch curve from (0,0) to (1,0) at `n` levels, in f64: each segment replaced by
/// four a third as long, turning +60°, −120°, +60°.
fn koch(n: u32) -> Vec<[f64; 4]> {
    let mut segments = vec![[0.0, 0.0, 1.0, 0.0]];
    for _ in 0..n {
        let mut next = Vec::new();
        for [x0, y0, x1, y1] in segments {
            let (dx, dy) = ((x1 - x0) / 3.0, (y1 - y0) / 3.0);
            let a = (x0 + dx, y0 + dy);
            let b = (x0 + 2.0 * dx, y0 + 2.0 * dy);
            let (c, s) = (60f64.to_radians().cos(), 60f64.to_radians().sin());
            let peak = (a.0 + dx * c - dy * s, a.1 + dx * s + dy * c);
            next.push([x0, y0, a.0, a.1]);
            next.push([a.0, a.1, peak.0, peak.1]);
            next.push([peak.0, peak.1, b.0, b.1]);
            next.push([b.0, b.1, x1, y1]);
        }
        segments = next;
    }
    segments
}

#[test]
fn matrix_koch_is_the_koch_curve() {
    for n in 0..=4u32 {
        let text = format!(
            "k {{\n  axiom: K({n})\n  angle: 60\n  \
             K(n) : n > 0 --> [ S(1/3) K(n-1) T(1) R(60) K(n-1) T(1) R(-60) R(-60) K(n-1) T(1) R(60) K(n-1) ]\n  \
             K(n) : n == 0 --> D\n}}\n"
        );
        let grammar = LsysFile::new(&text)
            .entry("k")
            .unwrap()
            .parametric()
            .unwrap();
        assert!(grammar.is_matrix());
        let ours: Vec<_> = Segments3::<'_, 17, 20>::new(&grammar, n + 1)
            .unwrap()
            .map(Result::unwrap)
            .collect();
        let model = koch(n);
        assert_eq!(ours.len(), 4usize.pow(n));
        for (s, m) in ours.iter().zip(&model) {
            let got = [s.start[0], s.start[1], s.end[0], s.end[1]].map(|v| v.to_f64());
            for (g, w) in got.iter().zip(m) {
                assert!((g - w).abs() < 1e-6, "level {n}: {got:?} vs {m:?}");
            }
            assert_eq!(s.start[2].to_f64(), 0.0);
        }
    }
}

/// `[` and `]` restore the matrix exactly (bitwise): after a branch that scales, turns and
/// moves, the next `D` is where it would be without the branch.
#[test]
fn push_and_pop_restore_the_matrix_exactly() {
    let text = "m {\n  axiom: T(0.7) R(33) [ S(0.37) R(71) T(2.9) D ] D\n  angle: 90\n}\n";
    let plain = "m {\n  axiom: T(0.7) R(33) D\n  angle: 90\n}\n";
    let last = |text: &str| {
        let grammar = LsysFile::new(text)
            .entry("m")
            .unwrap()
            .parametric()
            .unwrap();
        Segments3::<'_, 17, 20>::new(&grammar, 0)
            .unwrap()
            .map(Result::unwrap)
            .last()
            .unwrap()
    };
    assert_eq!(last(text), last(plain));
}
