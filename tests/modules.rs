//! The house's structure: no module imports itself through others, and the layers stand as
//! the developers' guide draws them.
//!
//! Every source file of the core, the simulator, the scene catalogue and the playground is
//! read as a module, and every path it names (`use` trees and paths in code, tests and
//! comments aside) as an arrow to the deepest module that path reaches. A cycle of arrows between files, or
//! between the core's top-level modules, fails; so does a family that imports another
//! family, or a shared layer that imports one above it. Paths that reach a module only
//! through a re-export (`crate::Name`, `super::Name` of a `mod.rs` that hands `Name` on)
//! count as arrows to the module that re-exports: import from where a name is defined.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// A crate's modules: each file's module path, its file and the paths it names.
struct Crate {
    modules: BTreeMap<Vec<String>, Module>,
}

struct Module {
    file: PathBuf,
    /// Absolute paths named, each as segments after `crate`.
    named: Vec<Vec<String>>,
}

impl Crate {
    /// Reads every `.rs` file under `src`.
    fn read(src: &Path) -> Self {
        let mut modules = BTreeMap::new();
        let mut files = Vec::new();
        collect(src, &mut files);
        for file in files {
            let relative = file.strip_prefix(src).unwrap();
            let mut path: Vec<String> = relative
                .iter()
                .map(|part| part.to_string_lossy().trim_end_matches(".rs").to_string())
                .collect();
            if matches!(
                path.last().map(String::as_str),
                Some("mod" | "lib" | "main")
            ) {
                path.pop();
            }
            if relative == Path::new("main.rs") {
                continue;
            }
            let text = fs::read_to_string(&file).unwrap();
            let named = named_paths(&code_of(&text), &path);
            modules.insert(path, Module { file, named });
        }
        Self { modules }
    }

    /// The module an absolute path reaches: its longest prefix that is a module.
    fn target(&self, path: &[String]) -> Option<Vec<String>> {
        (0..=path.len())
            .rev()
            .map(|n| path[..n].to_vec())
            .find(|prefix| self.modules.contains_key(prefix))
    }

    /// Arrows between distinct modules, each module to the ones it imports.
    fn arrows(&self) -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
        self.modules
            .iter()
            .map(|(from, module)| {
                let targets = module
                    .named
                    .iter()
                    .filter_map(|path| self.target(path))
                    .filter(|to| to != from)
                    .collect();
                (from.clone(), targets)
            })
            .collect()
    }

    /// The module's file, from the workspace.
    fn name(&self, module: &[String]) -> String {
        let file = &self.modules[module].file;
        file.strip_prefix(workspace())
            .unwrap_or(file)
            .display()
            .to_string()
    }
}

fn collect(dir: &Path, files: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            collect(&path, files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
}

/// The code of a file without comments, string contents and its test module.
fn code_of(text: &str) -> String {
    let mut code = String::new();
    let mut lines = text.lines().peekable();
    let mut in_string = false;
    while let Some(line) = lines.next() {
        if line.trim() == "#[cfg(test)]"
            && lines
                .peek()
                .is_some_and(|next| next.trim_start().starts_with("mod tests"))
        {
            break;
        }
        let mut escaped = false;
        for (index, c) in line.char_indices() {
            if in_string {
                in_string = escaped || c != '"';
                escaped = !escaped && c == '\\';
                continue;
            }
            if c == '"' && !line[..index].ends_with('\'') {
                in_string = true;
            } else if line[index..].starts_with("//") {
                break;
            } else {
                code.push(c);
            }
        }
        code.push('\n');
    }
    code
}

/// Every path a module's code names, made absolute (segments after `crate`).
fn named_paths(code: &str, module: &[String]) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    // `use` trees, braces expanded.
    let mut rest = code;
    while let Some(start) = use_statement(rest) {
        let after = &rest[start..];
        let Some(end) = after.find(';') else { break };
        for path in expand_tree(&after[..end]) {
            paths.extend(absolute(&path, module, true));
        }
        rest = &after[end..];
    }
    // Paths in code: `crate::a::b`, `super::a`, `self::a`.
    for anchor in ["crate::", "super::", "self::"] {
        let mut rest = code;
        while let Some(at) = rest.find(anchor) {
            let before = rest[..at].chars().next_back();
            let tail = &rest[at..];
            let end = tail
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(tail.len());
            if !before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                let segments: Vec<String> = tail[..end]
                    .split("::")
                    .filter(|s| !s.is_empty())
                    .map(str::to_string)
                    .collect();
                paths.extend(absolute(&segments, module, false));
            }
            rest = &tail[end.max(1)..];
        }
    }
    paths
}

/// Where the tree of the next `use` statement starts: after `use ` opening a line, behind
/// any `pub`, `pub(crate)` or `pub(super)`.
fn use_statement(text: &str) -> Option<usize> {
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim_start();
        let visible = ["pub(crate) ", "pub(super) ", "pub "]
            .iter()
            .find_map(|v| trimmed.strip_prefix(v))
            .unwrap_or(trimmed);
        if let Some(tree) = visible.strip_prefix("use ") {
            return Some(offset + line.len() - tree.len());
        }
        offset += line.len();
    }
    None
}

/// The paths of a `use` tree: `a::{b, c::{d, e}}` is `a::b`, `a::c::d`, `a::c::e`.
fn expand_tree(tree: &str) -> Vec<Vec<String>> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or(tree);
        let segments: Vec<String> = path
            .split("::")
            .map(|s| s.trim().to_string())
            .filter(|s| !s.is_empty() && s != "*")
            .collect();
        return vec![segments];
    };
    let prefix: Vec<String> = tree[..open]
        .split("::")
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .collect();
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (index, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..index]);
                start = index + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|part| !part.trim().is_empty())
        .flat_map(|part| {
            expand_tree(part).into_iter().map(|tail| {
                let mut path = prefix.clone();
                path.extend(tail.into_iter().filter(|s| s != "self"));
                path
            })
        })
        .collect()
}

/// A path as segments after `crate`. A path of a `use` that starts with a plain name is
/// taken as relative (`use read::ReadError` in `error`): if the name is no child module, it
/// reaches the module itself and draws no arrow. `None` for another path in code.
fn absolute(path: &[String], module: &[String], in_use: bool) -> Option<Vec<String>> {
    let mut base: Vec<String> = match path.first()?.as_str() {
        "crate" => Vec::new(),
        "self" | "super" => module.to_vec(),
        _ if in_use => return Some([module, path].concat()),
        _ => return None,
    };
    let mut rest = &path[1..];
    if path[0] == "super" {
        base.pop();
        while rest.first().is_some_and(|s| s == "super") {
            base.pop();
            rest = &rest[1..];
        }
    }
    base.extend(rest.iter().cloned());
    Some(base)
}

/// The cycles among `arrows`: each strongly connected set of two or more modules.
fn cycles<N: Ord + Clone>(arrows: &BTreeMap<N, BTreeSet<N>>) -> Vec<Vec<N>> {
    // Reachability by depth-first search from each node; a set of mutually reachable
    // nodes is a cycle. The graphs are small (a hundred files).
    let reach = |from: &N| {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.clone()];
        while let Some(node) = stack.pop() {
            for next in arrows.get(&node).into_iter().flatten() {
                if seen.insert(next.clone()) {
                    stack.push(next.clone());
                }
            }
        }
        seen
    };
    let reached: BTreeMap<N, BTreeSet<N>> = arrows.keys().map(|n| (n.clone(), reach(n))).collect();
    let mut found: Vec<Vec<N>> = Vec::new();
    for node in arrows.keys() {
        let mut set: Vec<N> = arrows
            .keys()
            .filter(|other| reached[node].contains(*other) && reached[*other].contains(node))
            .cloned()
            .collect();
        if set.len() > 1 && !found.iter().any(|cycle| cycle.contains(node)) {
            set.sort();
            found.push(set);
        }
    }
    found
}

fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The crates whose files must not import each other in a loop.
fn crates() -> Vec<(&'static str, Crate)> {
    let root = workspace();
    ["src", "simulator/src", "boards/scenes/src", "web/src"]
        .into_iter()
        .map(|src| (src, Crate::read(&root.join(src))))
        .collect()
}

#[test]
fn no_file_imports_itself_through_others() {
    for (src, krate) in crates() {
        let arrows = krate.arrows();
        assert!(arrows.len() >= 4, "{src}: too few modules read");
        let found = cycles(&arrows);
        let described: Vec<String> = found
            .iter()
            .map(|cycle| {
                let files: Vec<String> = cycle.iter().map(|m| krate.name(m)).collect();
                files.join(" <-> ")
            })
            .collect();
        assert!(
            found.is_empty(),
            "{src}: module cycles:\n{}",
            described.join("\n")
        );
    }
}

/// The core's layers, lowest first: a module may import its own layer's folder and the ones
/// below; families (every other top-level folder) import no other family.
const SHARED_LAYERS: [&str; 3] = ["math", "error", "render"];

#[test]
fn the_layers_stand_as_the_guide_draws_them() {
    let core = Crate::read(&workspace().join("src"));
    let layer = |top: &str| SHARED_LAYERS.iter().position(|l| *l == top);
    let mut wrong = Vec::new();
    for (from, targets) in core.arrows() {
        let Some(from_top) = from.first() else {
            continue; // the crate root hands everything on
        };
        for to in targets {
            let Some(to_top) = to.first() else {
                wrong.push(format!("{} imports the crate root", core.name(&from)));
                continue;
            };
            if to_top == from_top {
                continue;
            }
            let allowed = match (layer(from_top), layer(to_top)) {
                (Some(a), Some(b)) => b < a,
                (None, Some(_)) => true,
                (_, None) => false,
            };
            if !allowed {
                wrong.push(format!("{} imports {}", core.name(&from), core.name(&to)));
            }
        }
    }
    assert!(wrong.is_empty(), "layers crossed:\n{}", wrong.join("\n"));
}

/// The test sees what it must: a cycle and a crossing made on purpose are found.
#[test]
fn the_reader_finds_planted_cycles() {
    let module = |path: &[&str]| path.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let code = "use super::{a::{B, c}, d as e};\nfn f() { crate::math::real::Real::ONE; }\n\
                // use crate::hidden::X;\n\"crate::in_string\";";
    let named = named_paths(&code_of(code), &module(&["escape", "view"]));
    assert!(named.contains(&module(&["escape", "a", "B"])));
    assert!(named.contains(&module(&["escape", "a", "c"])));
    assert!(named.contains(&module(&["escape", "d"])));
    assert!(named.contains(&module(&["math", "real", "Real", "ONE"])));
    assert!(!named.iter().any(|p| p.contains(&"hidden".to_string())));
    assert!(!named.iter().any(|p| p.contains(&"in_string".to_string())));
    let arrows: BTreeMap<u8, BTreeSet<u8>> = [
        (1, BTreeSet::from([2])),
        (2, BTreeSet::from([3])),
        (3, BTreeSet::from([1])),
        (4, BTreeSet::from([1])),
    ]
    .into_iter()
    .collect();
    assert_eq!(cycles(&arrows), vec![vec![1, 2, 3]]);
}
