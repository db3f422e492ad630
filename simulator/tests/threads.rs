//! `--threads`: the same picture, byte for byte, on one thread or several.

mod common;

use common::{run, scratch, stderr};

#[test]
fn any_number_of_threads_draws_the_same_picture() {
    let dir = scratch("threads");
    let views: [&[&str]; 5] = [
        &["render", "mandelbrot", "--size", "300x200"],
        &[
            "render",
            "mandelbrot",
            "--size",
            "300x200",
            "--algorithm",
            "exact",
        ],
        &["render", "julia", "--c=-0.8,0.156", "--size", "257x131"],
        &[
            "render",
            "mandelbrot",
            "--size",
            "200x150",
            "--center=-0.745,0.11",
            "--width",
            "0.02",
            "--max-iter",
            "1000",
            "--palette",
            "smooth-classic",
        ],
        // By perturbation: each part computes its own reference orbit.
        &[
            "render",
            "mandelbrot",
            "--size",
            "160x96",
            "--center=-0.743643887,0.131825904",
            "--width",
            "1e-7",
            "--max-iter",
            "1500",
            "--precision",
            "perturbation",
        ],
    ];
    for (index, view) in views.iter().enumerate() {
        let mut pictures = Vec::new();
        for threads in ["1", "2", "5"] {
            let out = dir.join(format!("{index}-{threads}.png"));
            let mut args = vec!["--threads", threads];
            args.extend_from_slice(view);
            args.extend(["--out", out.to_str().unwrap()]);
            let output = run(&args);
            assert!(output.status.success(), "{args:?}: {}", stderr(&output));
            pictures.push(std::fs::read(&out).unwrap());
        }
        assert!(pictures.windows(2).all(|w| w[0] == w[1]), "{view:?}");
    }
    // Animations whose frames are made in parallel: the same file of frames.
    let animations: [&[&str]; 2] = [
        &[
            "animate",
            "noise",
            "--texture",
            "marble",
            "--size",
            "64x48",
            "--frames",
            "7",
        ],
        &[
            "animate",
            "attractor",
            "--kind",
            "lorenz",
            "--points-count",
            "4000",
            "--size",
            "64x48",
            "--frames",
            "5",
        ],
    ];
    for (index, animation) in animations.iter().enumerate() {
        let mut files = Vec::new();
        for threads in ["1", "2", "5"] {
            let out = dir.join(format!("animation-{index}-{threads}.gif"));
            let mut args = vec!["--threads", threads];
            args.extend_from_slice(animation);
            args.extend(["--out", out.to_str().unwrap()]);
            let output = run(&args);
            assert!(output.status.success(), "{args:?}: {}", stderr(&output));
            files.push(std::fs::read(&out).unwrap());
        }
        assert!(files.windows(2).all(|w| w[0] == w[1]), "{animation:?}");
        // Every frame is there, in order: not one frame repeated.
        let frames = {
            use image::AnimationDecoder;
            let bytes = std::io::Cursor::new(files[0].as_slice());
            let decoder = image::codecs::gif::GifDecoder::new(bytes).unwrap();
            let frames = decoder.into_frames().collect_frames().unwrap();
            // Consecutive frames differ: each is its own depth or turn.
            assert!(frames.windows(2).all(|w| w[0].buffer() != w[1].buffer()));
            frames.len()
        };
        let expected = if index == 0 { 7 } else { 5 };
        assert_eq!(frames, expected, "{animation:?}");
    }
    let refused = run(&["--threads", "0", "render", "mandelbrot"]);
    assert_eq!(refused.status.code(), Some(2));
}
