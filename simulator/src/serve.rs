//! `tinyfractal serve`: the playground (`web/page`) on 127.0.0.1, its files embedded in
//! the binary: the page, its scripts and the WebAssembly module cargo built with this crate
//! (`build.rs`). `--out DIR` writes the same files for any static file server instead.

use std::path::Path;

use clap::Args;

/// The page's files: name, content type, bytes.
type File = (&'static str, &'static str, &'static [u8]);

/// The page and its scripts.
const PAGE: [File; 3] = [
    (
        "index.html",
        "text/html; charset=utf-8",
        include_bytes!("../../web/page/index.html"),
    ),
    (
        "playground.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/page/playground.js"),
    ),
    (
        "worker.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../../web/page/worker.js"),
    ),
];

/// The WebAssembly module, if this binary was built with it.
#[cfg(tinyfractal_playground)]
const MODULE: Option<File> = Some((
    "tinyfractal_web.wasm",
    "application/wasm",
    include_bytes!(concat!(env!("OUT_DIR"), "/tinyfractal_web.wasm")),
));
#[cfg(not(tinyfractal_playground))]
const MODULE: Option<File> = None;

/// What to do without the module.
const NO_MODULE: &str = "this binary was built without the playground's WebAssembly module \
     (the `wasm32-unknown-unknown` target was missing): run `rustup target add \
     wasm32-unknown-unknown`, then `cargo run --release -- serve` again";

/// `serve`'s options.
#[derive(Debug, Clone, Args)]
pub struct ServeOptions {
    /// The port on 127.0.0.1 (0: any free one, printed)
    #[arg(long, value_name = "N", default_value_t = 8000)]
    pub port: u16,
    /// Write the page's files into DIR for any static file server instead of serving them
    #[arg(long, value_name = "DIR")]
    pub out: Option<std::path::PathBuf>,
}

/// Every file of the page, the module last.
fn files() -> Result<Vec<File>, String> {
    let module = MODULE.ok_or(NO_MODULE)?;
    Ok(PAGE.into_iter().chain([module]).collect())
}

/// The file a request's path names (`/` the page), if any.
fn file_for<'f>(files: &'f [File], url: &str) -> Option<&'f File> {
    let path = url.split(['?', '#']).next().unwrap_or_default();
    let name = match path.trim_start_matches('/') {
        "" => "index.html",
        name => name,
    };
    files.iter().find(|(file, _, _)| *file == name)
}

impl ServeOptions {
    pub fn run(&self) -> Result<(), String> {
        let files = files()?;
        if let Some(out) = &self.out {
            return write_files(&files, out);
        }
        let server = tiny_http::Server::http(("127.0.0.1", self.port)).map_err(|e| {
            format!(
                "serve: cannot listen on 127.0.0.1:{}: {e} (choose another --port, or 0 for any free one)",
                self.port
            )
        })?;
        let port = server
            .server_addr()
            .to_ip()
            .map_or(self.port, |address| address.port());
        crate::console::print(&format!(
            "serving the playground at http://127.0.0.1:{port}/ (Ctrl-C stops)\n"
        ))?;
        for request in server.incoming_requests() {
            let response = match file_for(&files, request.url()) {
                Some((_, kind, bytes)) => {
                    let header = tiny_http::Header::from_bytes("Content-Type", *kind)
                        .map_err(|()| "serve: a bad content type".to_string())?;
                    tiny_http::Response::from_data(*bytes).with_header(header)
                }
                None => {
                    tiny_http::Response::from_data(b"not found".as_slice()).with_status_code(404)
                }
            };
            // A browser that went away mid-answer is no reason to stop.
            let _ = request.respond(response);
        }
        Ok(())
    }
}

/// Writes `files` into the folder `out` (made if missing), each whole or not at all.
fn write_files(files: &[File], out: &Path) -> Result<(), String> {
    std::fs::create_dir_all(out)
        .map_err(|e| format!("serve --out {}: cannot make the folder: {e}", out.display()))?;
    let mut plan = crate::output::Plan::new();
    for (name, _, bytes) in files {
        plan.add("serve --out", &out.join(name), move |w| w.write_all(bytes));
    }
    plan.write()
}
