//! The playground in a real browser: headless Chromium loads the page from `tinyfractal
//! serve` and is driven over the DevTools protocol. Gallery scenes drawn in the page equal
//! the gallery's pictures pixel for pixel (an L-system, the Mandelbrot set, a deep zoom by
//! perturbation, an IFS); a system typed into the editor is drawn, and a broken one shows
//! the reader's error with its line and column.
//!
//! Needs Chromium (`chromium`, Debian's package): without it the test says so and passes,
//! except under `CI=true`, where it must run.

use std::io::{BufRead, BufReader};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;
use serde_json::{json, Value};
use tungstenite::{stream::MaybeTlsStream, Message, WebSocket};

/// Chromium's path, if it is installed.
fn chromium() -> Option<String> {
    ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|name| {
            Command::new(name)
                .arg("--version")
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status()
                .is_ok_and(|status| status.success())
        })
        .map(String::from)
}

/// A child process killed when dropped.
struct Running(Child);

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// `tinyfractal serve --port 0`, and the port it took.
fn serve() -> (Running, u16) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_tinyfractal"))
        .args(["serve", "--port", "0"])
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let running = Running(child);
    let port = line
        .split("127.0.0.1:")
        .nth(1)
        .and_then(|rest| rest.split('/').next())
        .and_then(|port| port.parse().ok())
        .unwrap_or_else(|| panic!("serve said {line:?}"));
    (running, port)
}

/// Headless Chromium with a page open, spoken to over the DevTools protocol.
struct Browser {
    _process: Running,
    _profile: tempfile::TempDir,
    socket: WebSocket<MaybeTlsStream<TcpStream>>,
    session: String,
    next: u64,
}

impl Browser {
    fn open(chromium: &str, url: &str) -> Self {
        let profile = tempfile::tempdir().unwrap();
        let mut child = Command::new(chromium)
            .args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--force-color-profile=srgb",
                "--remote-debugging-port=0",
            ])
            .arg(format!("--user-data-dir={}", profile.path().display()))
            .arg("about:blank")
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let stderr = BufReader::new(child.stderr.take().unwrap());
        let process = Running(child);
        let endpoint = stderr
            .lines()
            .map_while(Result::ok)
            .find_map(|line| {
                line.strip_prefix("DevTools listening on ")
                    .map(str::to_string)
            })
            .expect("Chromium did not say where DevTools listen");
        let (socket, _) = tungstenite::connect(endpoint.trim()).unwrap();
        let mut browser = Self {
            _process: process,
            _profile: profile,
            socket,
            session: String::new(),
            next: 0,
        };
        let target = browser.call("Target.createTarget", json!({ "url": url }));
        let attached = browser.call(
            "Target.attachToTarget",
            json!({ "targetId": target["targetId"], "flatten": true }),
        );
        browser.session = attached["sessionId"].as_str().unwrap().to_string();
        browser
    }

    /// Sends a command (to the page's session once attached) and waits for its result.
    fn call(&mut self, method: &str, params: Value) -> Value {
        self.next += 1;
        let id = self.next;
        let mut message = json!({ "id": id, "method": method, "params": params });
        if !self.session.is_empty() {
            message["sessionId"] = json!(self.session);
        }
        self.socket
            .send(Message::text(message.to_string()))
            .unwrap();
        loop {
            let Message::Text(text) = self.socket.read().unwrap() else {
                continue;
            };
            let reply: Value = serde_json::from_str(&text).unwrap();
            if reply["id"] == json!(id) {
                assert!(reply.get("error").is_none(), "{method}: {reply}");
                return reply["result"].clone();
            }
        }
    }

    /// The value of a JavaScript expression in the page (promises awaited).
    fn evaluate(&mut self, expression: &str) -> Value {
        let result = self.call(
            "Runtime.evaluate",
            json!({ "expression": expression, "awaitPromise": true, "returnByValue": true }),
        );
        assert!(
            result.get("exceptionDetails").is_none(),
            "{expression}: {result}"
        );
        result["result"]["value"].clone()
    }

    /// Waits until the page has answered more than `answers` requests (a picture drawn or
    /// an error shown), and returns its state: `drawn` or `error`.
    fn settled(&mut self, answers: u64) -> String {
        let started = Instant::now();
        loop {
            let state = self.evaluate(
                "document.body ? [document.body.dataset.state || '', \
                 Number(document.body.dataset.answers || 0)] : ['', 0]",
            );
            let answered = state[1].as_u64().unwrap_or(0);
            let state = state[0].as_str().unwrap_or_default().to_string();
            if answered > answers && (state == "drawn" || state == "error") {
                return state;
            }
            assert!(
                started.elapsed() < Duration::from_secs(120),
                "the page never finished: {state}"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// The canvas's pixels as RGB, and its size.
    fn canvas(&mut self) -> (u32, u32, Vec<u8>) {
        let value = self.evaluate(
            "(() => { const c = document.getElementById('picture'); \
             const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; \
             const rgb = []; for (let i = 0; i < d.length; i += 4) rgb.push(d[i], d[i + 1], d[i + 2]); \
             return [c.width, c.height, rgb]; })()",
        );
        let bytes = value[2]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap() as u8)
            .collect();
        (
            value[0].as_u64().unwrap() as u32,
            value[1].as_u64().unwrap() as u32,
            bytes,
        )
    }

    fn answers(&mut self) -> u64 {
        self.evaluate("document.body ? Number(document.body.dataset.answers || 0) : 0")
            .as_u64()
            .unwrap_or(0)
    }
}

/// A picture's pixels as RGB, and its size.
fn pixels(
    display: &SimulatorDisplay<embedded_graphics::pixelcolor::Rgb888>,
) -> (u32, u32, Vec<u8>) {
    let size = display.size();
    let mut rgb = Vec::new();
    for y in 0..size.height as i32 {
        for x in 0..size.width as i32 {
            let colour = display.get_pixel(Point::new(x, y));
            rgb.extend_from_slice(&[colour.r(), colour.g(), colour.b()]);
        }
    }
    (size.width, size.height, rgb)
}

/// How many pixels of two pictures of one size differ.
fn differing(a: &(u32, u32, Vec<u8>), b: &(u32, u32, Vec<u8>)) -> usize {
    assert_eq!((a.0, a.1), (b.0, b.1), "sizes differ");
    a.2.chunks(3)
        .zip(b.2.chunks(3))
        .filter(|(p, q)| p != q)
        .count()
}

/// Chromium, or `None` where the test may pass without it (not under CI).
fn browser_or_skip() -> Option<String> {
    let found = chromium();
    if found.is_none() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI=true needs Chromium for the playground's test: apt-get install chromium"
        );
        eprintln!("skipped: no Chromium (apt-get install chromium)");
    }
    found
}

/// A Fractint system for the editor, and its picture as `render lsystem` draws it.
fn drawn_system(text: &str, order: u32) -> (u32, u32, Vec<u8>) {
    let grammar = tinyfractal::LFile::new(text)
        .entries()
        .next()
        .unwrap()
        .unwrap()
        .grammar()
        .unwrap();
    pixels(
        &tinyfractal_simulator::scene::render(&grammar, order, 320, 240, None)
            .unwrap()
            .display,
    )
}

#[test]
fn the_page_draws_the_gallerys_pixels() {
    let Some(chromium) = browser_or_skip() else {
        return;
    };
    let (_server, port) = serve();
    for name in ["koch-snowflake", "mandelbrot", "deep-spiral", "ifs-fern"] {
        let url = format!("http://127.0.0.1:{port}/index.html?scene={name}&embed=1");
        let mut browser = Browser::open(&chromium, &url);
        assert_eq!(browser.settled(0), "drawn", "{name}");
        let shown = browser.canvas();
        let (picture, ..) = tinyfractal_simulator::gallery::render_named(name)
            .unwrap()
            .unwrap();
        let expected = pixels(&picture);
        assert_eq!(
            differing(&shown, &expected),
            0,
            "{name}: the canvas differs"
        );
        // The canvas is at the page's top left at its natural size.
        let placed = browser.evaluate(
            "(() => { const r = document.getElementById('picture').getBoundingClientRect(); \
             return [r.left, r.top, r.width, r.height]; })()",
        );
        assert_eq!(
            placed,
            json!([0, 0, expected.0, expected.1]),
            "{name}: the embedded canvas's place"
        );
    }
}

#[test]
fn typing_a_rule_redraws_and_a_broken_one_shows_the_readers_error() {
    let Some(chromium) = browser_or_skip() else {
        return;
    };
    let (_server, port) = serve();
    let koch = "Koch {\n  Angle 6\n  Axiom F--F--F\n  F=F+F--F+F\n}\n";
    let url = format!(
        "http://127.0.0.1:{port}/index.html?order=3&lsystem={}",
        koch.replace('\n', "%0A")
            .replace(' ', "%20")
            .replace('+', "%2B")
    );
    let mut browser = Browser::open(&chromium, &url);
    assert_eq!(browser.settled(0), "drawn");
    assert_eq!(differing(&browser.canvas(), &drawn_system(koch, 3)), 0);

    // Typed: the page hears an input event, as from the keyboard.
    let type_text = |browser: &mut Browser, text: &str| {
        let answers = browser.answers();
        browser.evaluate(&format!(
            "(() => {{ const s = document.getElementById('source'); s.value = {}; \
             s.dispatchEvent(new Event('input')); }})()",
            json!(text)
        ));
        browser.settled(answers)
    };
    let square = "Square {\n  Angle 4\n  Axiom F+F+F+F\n  F=FF+F+F+F+FF\n}\n";
    assert_eq!(type_text(&mut browser, square), "drawn");
    assert_eq!(differing(&browser.canvas(), &drawn_system(square, 3)), 0);

    let broken = "Square {\n  Angle x4\n  Axiom F+F+F+F\n  F=FF+F+F+F+FF\n}\n";
    assert_eq!(type_text(&mut browser, broken), "error");
    let message = browser.evaluate("document.getElementById('status').textContent");
    let message = message.as_str().unwrap();
    assert!(
        message.contains("angle") && message.contains("line 2, column 9"),
        "the reader's error with its place: {message}"
    );
    // The picture before the error stays: the page is not left blank.
    assert_eq!(differing(&browser.canvas(), &drawn_system(square, 3)), 0);

    // The angle field rewrites the system's angle line: mended, and drawn at 8 divisions.
    let answers = browser.answers();
    browser.evaluate(
        "(() => { const a = document.getElementById('angle'); a.value = '8'; \
         a.dispatchEvent(new Event('change')); })()",
    );
    assert_eq!(browser.settled(answers), "drawn");
    let eighths = square.replace("Angle 4", "Angle 8");
    let text = browser.evaluate("document.getElementById('source').value");
    assert_eq!(text.as_str(), Some(eighths.as_str()));
    assert_eq!(differing(&browser.canvas(), &drawn_system(&eighths, 3)), 0);
}

/// `serve --out` writes the page's files for any static file server: the page, its two
/// scripts and the module, under 1 MB together (docs/playground.md states the sizes).
#[test]
fn the_pages_files_are_written_whole_and_small() {
    let out = tempfile::tempdir().unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_tinyfractal"))
        .args(["serve", "--out"])
        .arg(out.path())
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&run.stderr);
    if !run.status.success() && said.contains("wasm32-unknown-unknown") {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI=true needs the playground's module: {said}"
        );
        eprintln!("skipped: {said}");
        return;
    }
    assert!(run.status.success(), "{said}");
    let mut total = 0;
    for name in [
        "index.html",
        "playground.js",
        "worker.js",
        "tinyfractal_web.wasm",
    ] {
        let bytes = std::fs::read(out.path().join(name)).unwrap();
        eprintln!("{name}: {} bytes", bytes.len());
        total += bytes.len();
    }
    let module = std::fs::read(out.path().join("tinyfractal_web.wasm")).unwrap();
    assert_eq!(&module[..4], b"\0asm", "a WebAssembly module");
    assert!(total < 1 << 20, "the page is {total} bytes: over 1 MB");
}

/// The explorer draws its first view (the gallery's Mandelbrot set) in budgeted steps,
/// showing it as it grows, and ends with the gallery's picture.
#[test]
fn the_explorer_draws_in_steps_to_the_gallerys_picture() {
    let Some(chromium) = browser_or_skip() else {
        return;
    };
    let (_server, port) = serve();
    let mut browser = Browser::open(&chromium, &format!("http://127.0.0.1:{port}/"));
    assert_eq!(browser.settled(0), "drawn");
    let (picture, ..) = tinyfractal_simulator::gallery::render_named("mandelbrot")
        .unwrap()
        .unwrap();
    assert_eq!(differing(&browser.canvas(), &pixels(&picture)), 0);
    let status = browser.evaluate("document.getElementById('status').textContent");
    assert!(
        status
            .as_str()
            .unwrap_or_default()
            .starts_with("tier=standard"),
        "the tier shown: {status}"
    );
}
