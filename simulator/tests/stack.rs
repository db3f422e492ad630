//! The global pool's threads, which the gallery's scenes and an escape-time picture's
//! parts run on without `--threads`, have the stack `with_threads` promises.
//!
//! One test in a process of its own, so that nothing made the global pool before it.

use tinyfractal_simulator::parallel::with_threads;

/// A frame four times a thread's default stack: it aborts the process on a default
/// thread.
#[inline(never)]
fn deep() -> usize {
    let frame = std::hint::black_box([1u8; 8 << 20]);
    frame.iter().map(|&byte| usize::from(byte)).sum()
}

#[test]
fn the_global_pool_holds_frames_beyond_a_default_stack() {
    let both = with_threads(None, || rayon::join(deep, deep));
    assert_eq!(both, Ok((8 << 20, 8 << 20)));
}
