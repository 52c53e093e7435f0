//! `cargo xtask tidy`: the structural rules of the workspace.
//!
//! 1. Dependencies only point down the pyramid (`docs/ARCHITECTURE.md`,
//!    "The pyramid"): a normal (or build) dependency of a crate under
//!    `crates/` on another workspace crate must be in the allowed table
//!    below. Dev-dependencies may point anywhere, and the dev-only crates
//!    ([`DEV_ONLY`]) may be nothing else.
//! 2. Every declared dependency (normal, build or dev) of every package of
//!    the repository is used by that package's code, and every
//!    `[workspace.dependencies]` entry is taken by some member
//!    ([`check_unused_dependencies`]).
//! 3. Every `.rs` file of the repository (outside build output) starts with
//!    a `//!` header comment.
//! 4. No doc or comment points outside the repository: no relative path
//!    climbing above the root, no absolute path into the machine it was
//!    written on, no name of a file that only exists beside the repository
//!    ([`check_external_references`]).
//!
//! `Cargo.toml` files are read with a small hand parser that understands
//! the forms this workspace uses: `name.workspace = true`, `name = { path =
//! ".." }`, `name = { workspace = true, .. }`, `[dependencies.name]` tables
//! and `package = ".."` renames.

use anyhow::{bail, Context, Result};
use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

/// The allowed normal dependencies of every crate under `crates/` on other
/// workspace crates (the table of `docs/ARCHITECTURE.md`). A crate missing
/// here is an error.
pub const ALLOWED: &[(&str, &[&str])] = &[
    ("robust-arith", &[]),
    ("topology", &["robust-arith"]),
    ("shadow-1d", &["topology", "robust-arith"]),
    ("shadow-2d", &["shadow-1d", "topology", "robust-arith"]),
    ("boolean-2d", SHADOWS),
    ("boolean-3d", SHADOWS),
    ("simplify-2d", &["shadow-1d", "topology", "robust-arith"]),
    ("smooth", BELOW_SMOOTH),
    ("umbra", ALGORITHMS),
    ("umbra-cli", &["umbra"]),
    ("umbra-py", &["umbra"]),
    ("test-support", ALGORITHMS),
];

/// `shadow-2d` and below: what the basic Booleans may use.
const SHADOWS: &[&str] = &["shadow-2d", "shadow-1d", "topology", "robust-arith"];

/// The Booleans, the sweep and below: what smoothing may use.
const BELOW_SMOOTH: &[&str] = &[
    "boolean-2d",
    "boolean-3d",
    "simplify-2d",
    "shadow-2d",
    "shadow-1d",
    "topology",
    "robust-arith",
];

/// Every algorithm crate: what the facade (and `test-support`) may use.
const ALGORITHMS: &[&str] = &[
    "smooth",
    "boolean-2d",
    "boolean-3d",
    "simplify-2d",
    "shadow-2d",
    "shadow-1d",
    "topology",
    "robust-arith",
];

/// Crates for development only: a crate under `crates/` may take them as
/// dev-dependencies, never as normal or build dependencies (so no test code
/// is reachable from library code). `xtask`, `benches` and `fuzz` sit
/// outside `crates/` and may use them freely.
pub const DEV_ONLY: &[&str] = &["test-support"];

/// `[workspace.dependencies]` entries kept although no member takes them
/// yet, each with the reason. Keep this short: an entry here is a promise.
pub const RESERVED_WORKSPACE_DEPS: &[(&str, &str)] = &[];

/// Declared dependencies a package keeps without naming them in its code,
/// as `(package, dependency, reason)`. Empty: every entry so far was dead.
pub const UNUSED_DEPENDENCY_EXCEPTIONS: &[(&str, &str, &str)] = &[];

/// One dependency entry of a manifest.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dep {
    /// The key in the manifest: the name code uses (with `-` read as `_`).
    pub key: String,
    /// The package name (after any `package = ".."` rename).
    pub package: String,
    /// The section kind: `dependencies`, `dev-dependencies` or
    /// `build-dependencies`.
    pub kind: String,
    /// `true` for `workspace = true`.
    pub workspace: bool,
    /// The `path = ".."` value, if any.
    pub path: Option<String>,
}

/// A parsed manifest: the package name and every dependency entry.
#[derive(Clone, Debug, Default)]
pub struct Manifest {
    /// `[package] name`.
    pub name: Option<String>,
    /// Every dependency entry, from every dependency section.
    pub deps: Vec<Dep>,
    /// `[workspace.dependencies]` entries (root manifest only).
    pub workspace_deps: Vec<Dep>,
}

/// Strips a trailing comment that is not inside a string.
fn strip_comment(line: &str) -> &str {
    let mut in_str = false;
    for (i, c) in line.char_indices() {
        match c {
            '"' => in_str = !in_str,
            '#' if !in_str => return &line[..i],
            _ => {}
        }
    }
    line
}

/// The value of `key = "value"` or `key = true` inside an inline table or
/// a table body.
fn inline_value(body: &str, key: &str) -> Option<String> {
    for part in body.split(',') {
        let part = part
            .trim()
            .trim_start_matches('{')
            .trim_end_matches('}')
            .trim();
        if let Some((k, v)) = part.split_once('=') {
            if k.trim() == key {
                return Some(v.trim().trim_matches('"').to_string());
            }
        }
    }
    None
}

/// The dependency kind of a section header, if it is a dependency section:
/// `[dependencies]`, `[dev-dependencies]`, `[build-dependencies]`,
/// `[target.'cfg(..)'.dependencies]`, `[workspace.dependencies]`, and the
/// `[dependencies.name]` table forms. Returns `(kind, table-form name)`.
fn dep_section(header: &str) -> Option<(String, Option<String>)> {
    let h = header.trim();
    let h = h.strip_prefix("target.").map_or(h, |rest| {
        // Skip the quoted or dotted target spec.
        if let Some(r) = rest.strip_prefix('\'') {
            r.split_once("'.").map_or(rest, |(_, t)| t)
        } else if let Some(r) = rest.strip_prefix('"') {
            r.split_once("\".").map_or(rest, |(_, t)| t)
        } else {
            rest.split_once('.').map_or(rest, |(_, t)| t)
        }
    });
    for kind in [
        "workspace.dependencies",
        "dev-dependencies",
        "build-dependencies",
        "dependencies",
    ] {
        if h == kind {
            return Some((kind.to_string(), None));
        }
        if let Some(name) = h.strip_prefix(kind).and_then(|r| r.strip_prefix('.')) {
            return Some((kind.to_string(), Some(name.trim_matches('"').to_string())));
        }
    }
    None
}

/// Parses the parts of a `Cargo.toml` tidy needs.
pub fn parse_manifest(text: &str) -> Manifest {
    let mut m = Manifest::default();
    let mut section = String::new();
    // (kind, name) of a `[dependencies.name]` table being read.
    let mut table: Option<(String, Dep)> = None;
    let flush = |m: &mut Manifest, table: &mut Option<(String, Dep)>| {
        if let Some((kind, dep)) = table.take() {
            if kind == "workspace.dependencies" {
                m.workspace_deps.push(dep);
            } else {
                m.deps.push(dep);
            }
        }
    };
    for raw in text.lines() {
        let line = strip_comment(raw).trim();
        if line.is_empty() {
            continue;
        }
        if line.starts_with('[') {
            flush(&mut m, &mut table);
            section = line.trim_matches(|c| c == '[' || c == ']').to_string();
            if let Some((kind, Some(name))) = dep_section(&section) {
                table = Some((
                    kind.clone(),
                    Dep {
                        key: name.clone(),
                        package: name,
                        kind,
                        workspace: false,
                        path: None,
                    },
                ));
            }
            continue;
        }
        let Some((key, value)) = line.split_once('=') else {
            continue;
        };
        let (key, value) = (key.trim(), value.trim());
        if section == "package" && key == "name" {
            m.name = Some(value.trim_matches('"').to_string());
            continue;
        }
        if let Some((_, dep)) = table.as_mut() {
            match key {
                "workspace" => dep.workspace = value == "true",
                "path" => dep.path = Some(value.trim_matches('"').to_string()),
                "package" => dep.package = value.trim_matches('"').to_string(),
                _ => {}
            }
            continue;
        }
        let Some((kind, None)) = dep_section(&section) else {
            continue;
        };
        let (name, workspace_dotted) = match key.strip_suffix(".workspace") {
            Some(n) => (n.trim(), value == "true"),
            None => (key, false),
        };
        let name = name.trim_matches('"');
        let dep = Dep {
            key: name.to_string(),
            package: inline_value(value, "package").unwrap_or_else(|| name.to_string()),
            kind: kind.clone(),
            workspace: workspace_dotted
                || inline_value(value, "workspace").as_deref() == Some("true"),
            path: inline_value(value, "path"),
        };
        if kind == "workspace.dependencies" {
            m.workspace_deps.push(dep);
        } else {
            m.deps.push(dep);
        }
    }
    flush(&mut m, &mut table);
    m
}

/// The workspace root (the parent of the xtask crate).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

/// The dependency rule: every violation as a message.
pub fn check_dependencies(root: &Path) -> Result<Vec<String>> {
    let root_text = fs::read_to_string(root.join("Cargo.toml"))
        .with_context(|| format!("reading {}", root.join("Cargo.toml").display()))?;
    let root_manifest = parse_manifest(&root_text);
    // Workspace dependency name -> path (if a path dependency).
    let ws_paths: BTreeMap<String, Option<String>> = root_manifest
        .workspace_deps
        .iter()
        .map(|d| (d.package.clone(), d.path.clone()))
        .collect();
    let allowed: BTreeMap<&str, &[&str]> = ALLOWED.iter().copied().collect();

    // Every crate directory under crates/ and its package name.
    let mut crates: BTreeMap<PathBuf, String> = BTreeMap::new();
    let crates_dir = root.join("crates");
    let mut entries: Vec<_> = fs::read_dir(&crates_dir)
        .with_context(|| format!("reading {}", crates_dir.display()))?
        .collect::<std::io::Result<_>>()?;
    entries.sort_by_key(|e| e.file_name());
    let mut problems = Vec::new();
    let mut manifests = Vec::new();
    for entry in entries {
        let dir = entry.path();
        let toml = dir.join("Cargo.toml");
        if !toml.is_file() {
            continue;
        }
        let text =
            fs::read_to_string(&toml).with_context(|| format!("reading {}", toml.display()))?;
        let m = parse_manifest(&text);
        let Some(name) = m.name.clone() else {
            problems.push(format!("{}: no [package] name", toml.display()));
            continue;
        };
        let canon = dir.canonicalize().unwrap_or(dir.clone());
        crates.insert(canon, name.clone());
        manifests.push((dir, name, m));
    }
    for (dir, name, m) in &manifests {
        let Some(ok) = allowed.get(name.as_str()) else {
            problems.push(format!(
                "crates/{}: crate '{name}' is not in the dependency table of docs/ARCHITECTURE.md; add it there and to xtask/src/tidy.rs ALLOWED with its allowed dependencies",
                dir.file_name().map_or_else(String::new, |f| f.to_string_lossy().into_owned())
            ));
            continue;
        };
        for dep in &m.deps {
            if dep.kind == "dev-dependencies" {
                continue; // Dev-dependencies may reach higher crates.
            }
            // Resolve to a local path, if it is a path dependency.
            let path = if dep.workspace {
                ws_paths
                    .get(&dep.package)
                    .cloned()
                    .flatten()
                    .map(|p| root.join(p))
            } else {
                dep.path.as_ref().map(|p| dir.join(p))
            };
            let Some(path) = path else {
                continue; // A registry crate.
            };
            let canon = path.canonicalize().unwrap_or(path.clone());
            match crates.get(&canon) {
                Some(target) if DEV_ONLY.contains(&target.as_str()) => problems.push(format!(
                    "crates/{}/Cargo.toml: '{name}' has a {} on the dev-only crate '{target}'; take it as a dev-dependency",
                    dir.file_name().map_or_else(String::new, |f| f.to_string_lossy().into_owned()),
                    dep.kind.trim_end_matches('s').replace("dependencie", "dependency"),
                )),
                Some(target) if ok.contains(&target.as_str()) => {}
                Some(target) => problems.push(format!(
                    "crates/{}/Cargo.toml: '{name}' has a {} on '{target}', which is not below it in the pyramid (allowed: {})",
                    dir.file_name().map_or_else(String::new, |f| f.to_string_lossy().into_owned()),
                    dep.kind.trim_end_matches('s').replace("dependencie", "dependency"),
                    if ok.is_empty() { "none".to_string() } else { ok.join(", ") }
                )),
                None => problems.push(format!(
                    "crates/{}/Cargo.toml: '{name}' has a path {} on '{}' ({}), which is not a crate under crates/",
                    dir.file_name().map_or_else(String::new, |f| f.to_string_lossy().into_owned()),
                    dep.kind.trim_end_matches('s').replace("dependencie", "dependency"),
                    dep.package,
                    path.display()
                )),
            }
        }
    }
    Ok(problems)
}

/// Directories never scanned: build output, VCS data and hidden
/// directories other than the repository's own configuration (`.ci`,
/// `.cargo`, `.github`).
fn skipped_dir(name: &str) -> bool {
    name.starts_with("target")
        || name == "node_modules"
        || (name.starts_with('.') && ![".ci", ".cargo", ".github"].contains(&name))
}

/// Every file below `root` (sorted), leaving out build output, VCS data
/// and the directories `enter` refuses.
fn files_below(root: &Path, enter: impl Fn(&Path) -> bool) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).with_context(|| format!("reading {}", dir.display()))? {
            let entry = entry?;
            let path = entry.path();
            let ty = entry.file_type()?;
            if ty.is_dir() {
                if !skipped_dir(&entry.file_name().to_string_lossy()) && enter(&path) {
                    stack.push(path);
                }
            } else if ty.is_file() {
                out.push(path);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// The header rule: every `.rs` file not starting with `//!`.
pub fn check_headers(root: &Path) -> Result<Vec<String>> {
    let mut problems = Vec::new();
    for path in files_below(root, |_| true)? {
        if path.extension().is_some_and(|e| e == "rs") {
            let text =
                fs::read_to_string(&path).with_context(|| format!("reading {}", path.display()))?;
            if !text.starts_with("//!") {
                let rel = path.strip_prefix(root).unwrap_or(&path);
                problems.push(format!(
                    "{}: does not start with a `//!` header comment",
                    rel.display()
                ));
            }
        }
    }
    problems.sort();
    Ok(problems)
}

/// A comment of a Rust source file: its first line (1-based), whether it
/// is a doc comment (`///`, `//!`, `/** */`, `/*! */`) and its text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comment {
    /// The line the comment starts on.
    pub line: usize,
    /// A doc comment.
    pub doc: bool,
    /// The text after the comment marker.
    pub text: String,
}

/// Splits Rust source into code (comments blanked, strings kept) and its
/// comments. A small lexer: it knows line and nested block comments,
/// string, byte-string and raw-string literals, and tells character
/// literals from lifetimes, which is all that separating the two needs.
pub fn split_rust(src: &str) -> (String, Vec<Comment>) {
    let c: Vec<char> = src.chars().collect();
    let mut code = String::with_capacity(src.len());
    let mut comments = Vec::new();
    let mut line = 1;
    let mut i = 0;
    while i < c.len() {
        let ch = c[i];
        let next = c.get(i + 1).copied();
        if ch == '/' && next == Some('/') {
            let start = i;
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
            let body: String = c[start + 2..i].iter().collect();
            let doc = body.starts_with('/') && !body.starts_with("//") || body.starts_with('!');
            let text = if doc { body[1..].to_string() } else { body };
            comments.push(Comment { line, doc, text });
            continue;
        }
        if ch == '/' && next == Some('*') {
            let (start_line, start) = (line, i);
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    if c[i] == '\n' {
                        line += 1;
                        code.push('\n');
                    }
                    i += 1;
                }
            }
            let body: String = c[start + 2..i.saturating_sub(2).max(start + 2)]
                .iter()
                .collect();
            let doc = body.starts_with('*') && !body.starts_with("**") || body.starts_with('!');
            comments.push(Comment {
                line: start_line,
                doc,
                text: body,
            });
            continue;
        }
        // Raw strings: r"..", r#".."#, br#".."#.
        let raw_at = if ch == 'r' {
            Some(i + 1)
        } else if ch == 'b' && next == Some('r') {
            Some(i + 2)
        } else {
            None
        };
        let ident_before = i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_');
        if let (Some(mut j), false) = (raw_at, ident_before) {
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if c.get(j) == Some(&'"') {
                let close: Vec<char> = std::iter::once('"')
                    .chain(std::iter::repeat_n('#', hashes))
                    .collect();
                code.extend(&c[i..=j]);
                j += 1;
                while j < c.len() && !c[j..].starts_with(&close) {
                    if c[j] == '\n' {
                        line += 1;
                    }
                    code.push(c[j]);
                    j += 1;
                }
                let end = (j + close.len()).min(c.len());
                code.extend(&c[j.min(c.len())..end]);
                i = end;
                continue;
            }
        }
        if ch == '"' {
            code.push('"');
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' && i + 1 < c.len() {
                    code.push(c[i]);
                    i += 1;
                }
                if c[i] == '\n' {
                    line += 1;
                }
                code.push(c[i]);
                i += 1;
            }
            if i < c.len() {
                code.push('"');
                i += 1;
            }
            continue;
        }
        if ch == '\'' {
            // A character literal ('x', '\n', '\u{..}') or a lifetime.
            let lit_end = if next == Some('\\') {
                (i + 2..c.len().min(i + 12)).find(|&k| c[k] == '\'')
            } else if c.get(i + 2) == Some(&'\'') {
                Some(i + 2)
            } else {
                None
            };
            if let Some(e) = lit_end {
                code.extend(&c[i..=e]);
                i = e + 1;
                continue;
            }
        }
        if ch == '\n' {
            line += 1;
        }
        code.push(ch);
        i += 1;
    }
    (code, comments)
}

/// The code of a Rust file for the dependency scan: the code proper and the
/// code blocks of its doc comments (doc tests use dependencies too).
fn scanned_code(src: &str) -> String {
    let (mut code, comments) = split_rust(src);
    let mut fenced = false;
    for c in comments.iter().filter(|c| c.doc) {
        for l in c.text.lines() {
            if l.trim_start().starts_with("```") {
                fenced = !fenced;
            } else if fenced {
                code.push('\n');
                code.push_str(l.trim_start().trim_start_matches("# "));
            }
        }
    }
    code
}

/// Whether `code` names the crate `ident` as a path root: `ident::..`,
/// `use ident` or `extern crate ident`, not as part of a longer name.
pub fn names_crate(code: &str, ident: &str) -> bool {
    let is_ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut from = 0;
    while let Some(pos) = code[from..].find(ident) {
        let at = from + pos;
        from = at + ident.len();
        let before = code[..at].chars().next_back();
        if before.is_some_and(is_ident) {
            continue;
        }
        let rest = &code[from..];
        if rest.chars().next().is_some_and(is_ident) {
            continue;
        }
        if rest.trim_start().starts_with("::") && !code[..at].trim_end().ends_with("::") {
            return true;
        }
        let head = code[..at].trim_end();
        if head.ends_with("use") || head.ends_with("extern crate") {
            return true;
        }
    }
    false
}

/// The `.rs` files of a package directory, leaving out build output and
/// nested packages (directories with their own `Cargo.toml`).
fn package_sources(dir: &Path) -> Result<Vec<PathBuf>> {
    let files = files_below(dir, |d| !d.join("Cargo.toml").is_file())?;
    Ok(files
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect())
}

/// Every `Cargo.toml` with a `[package]` below `root` (outside build
/// output), with its directory.
fn packages(root: &Path) -> Result<Vec<(PathBuf, Manifest)>> {
    let mut out = Vec::new();
    for toml in files_below(root, |_| true)? {
        if toml.file_name().is_some_and(|n| n == "Cargo.toml") {
            let text =
                fs::read_to_string(&toml).with_context(|| format!("reading {}", toml.display()))?;
            let m = parse_manifest(&text);
            if let (Some(dir), Some(_)) = (toml.parent(), &m.name) {
                out.push((dir.to_path_buf(), m));
            }
        }
    }
    Ok(out)
}

/// The unused-dependency rule: a dependency (normal, build or dev) of any
/// package of the repository that none of the package's `.rs` files names
/// (its key with `-` read as `_`, as a path root, in code or in a doc
/// test), and a `[workspace.dependencies]` entry no package takes, unless
/// listed in [`RESERVED_WORKSPACE_DEPS`]. A crate used only for a derive
/// macro is still named (`use serde::Serialize`), so it passes; a
/// dependency kept only to switch a feature of another crate must be
/// listed in [`UNUSED_DEPENDENCY_EXCEPTIONS`] with its reason.
pub fn check_unused_dependencies(root: &Path) -> Result<Vec<String>> {
    let mut problems = Vec::new();
    let pkgs = packages(root)?;
    let mut taken: Vec<String> = Vec::new();
    for (dir, m) in &pkgs {
        let name = m.name.clone().unwrap_or_default();
        let rel = dir.strip_prefix(root).unwrap_or(dir).display().to_string();
        let rel = if rel.is_empty() { ".".to_string() } else { rel };
        let mut code = String::new();
        for f in package_sources(dir)? {
            let text =
                fs::read_to_string(&f).with_context(|| format!("reading {}", f.display()))?;
            code.push_str(&scanned_code(&text));
            code.push('\n');
        }
        for dep in &m.deps {
            if dep.workspace {
                taken.push(dep.key.clone());
            }
            let excused = UNUSED_DEPENDENCY_EXCEPTIONS
                .iter()
                .any(|(p, d, _)| *p == name && *d == dep.key);
            if !excused && !names_crate(&code, &dep.key.replace('-', "_")) {
                problems.push(format!(
                    "{rel}/Cargo.toml: '{name}' declares the {} '{}' but no code of it uses `{}`; remove it",
                    dep.kind.trim_end_matches('s').replace("dependencie", "dependency"),
                    dep.key,
                    dep.key.replace('-', "_"),
                ));
            }
        }
    }
    let root_text = fs::read_to_string(root.join("Cargo.toml"))
        .with_context(|| format!("reading {}", root.join("Cargo.toml").display()))?;
    for dep in parse_manifest(&root_text).workspace_deps {
        let reserved = RESERVED_WORKSPACE_DEPS.iter().any(|(d, _)| *d == dep.key);
        if !reserved && !taken.contains(&dep.key) {
            problems.push(format!(
                "Cargo.toml: [workspace.dependencies] '{}' is taken by no member; remove it",
                dep.key
            ));
        }
    }
    Ok(problems)
}

/// The text files the external-reference rule reads, by extension, and
/// whether all of the text is documentation (`true`) or only its comments.
fn doc_kind(name: &str) -> Option<bool> {
    let ext = name.rsplit_once('.').map(|(_, e)| e)?;
    match ext {
        "md" | "txt" => Some(true),
        "rs" | "toml" | "py" | "yml" | "yaml" | "sh" => Some(false),
        _ => None,
    }
}

/// The comments of a file that is not all documentation: Rust comments, or
/// `#` comments (outside strings) for TOML, Python, YAML and shell.
fn comments_of(name: &str, text: &str) -> Vec<(usize, String)> {
    if name.ends_with(".rs") {
        let (_, comments) = split_rust(text);
        return comments
            .into_iter()
            .flat_map(|c| {
                c.text
                    .lines()
                    .enumerate()
                    .map(|(k, l)| (c.line + k, l.to_string()))
                    .collect::<Vec<_>>()
            })
            .collect();
    }
    text.lines()
        .enumerate()
        .filter_map(|(k, l)| {
            let code = strip_comment(l);
            (code.len() < l.len()).then(|| (k + 1, l[code.len()..].to_string()))
        })
        .collect()
}

/// What in one line of documentation points outside the repository, for a
/// file in the directory `dir`, `depth` directories below the root: a
/// relative path that climbs above the root, or climbs to a name that does
/// not exist in the repository (such as a directory beside it).
fn external_reference(text: &str, dir: &Path, depth: usize) -> Option<String> {
    let names = [concat!("DESIGN", ".md"), concat!("thesis", ".txt")];
    if let Some(n) = names.iter().find(|n| text.contains(*n)) {
        return Some(format!(
            "names `{n}`, a file outside the repository (cite the dissertation by title and section; the design rules live in docs/ARCHITECTURE.md)"
        ));
    }
    let absolute = ["/work/", "/tmp/", "/home/", "/root/", "/Users/", "/mnt/"];
    if let Some(a) = absolute.iter().find(|a| {
        text.match_indices(*a).any(|(at, _)| {
            !text[..at]
                .chars()
                .next_back()
                .is_some_and(|ch| ch.is_alphanumeric() || "_.-/".contains(ch))
        })
    }) {
        return Some(format!(
            "points to the absolute path `{a}..` on the machine it was written on"
        ));
    }
    let mut from = 0;
    while let Some(pos) = text[from..].find("../") {
        let at = from + pos;
        let mut k = 0;
        let mut j = at;
        while text[j..].starts_with("../") {
            k += 1;
            j += 3;
        }
        from = j;
        if text[..at].ends_with('.') {
            continue;
        }
        let end = text[at..]
            .find(|ch: char| ch.is_whitespace() || "`)'\"]>,;".contains(ch))
            .map_or(text.len(), |e| at + e);
        let shown = &text[at..end];
        if k > depth {
            return Some(format!(
                "has the relative path `{shown}`, which climbs out of the repository"
            ));
        }
        let first = text[j..end]
            .split(['/', '#'])
            .next()
            .unwrap_or("")
            .trim_end_matches(['.', ':']);
        let mut target = dir.to_path_buf();
        for _ in 0..k {
            target.pop();
        }
        if !first.is_empty() && !target.join(first).exists() {
            return Some(format!(
                "has the relative path `{shown}`, which leads to nothing in the repository"
            ));
        }
    }
    None
}

/// The external-reference rule: every doc or comment line (Markdown and
/// text files whole; comments of Rust, TOML, Python, YAML and shell files)
/// that names a file beside the repository, an absolute path of the
/// machine, or a relative path climbing above the repository root.
pub fn check_external_references(root: &Path) -> Result<Vec<String>> {
    let mut problems = Vec::new();
    for path in files_below(root, |_| true)? {
        let name = path
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let Ok(text) = fs::read_to_string(&path) else {
            continue; // Not UTF-8: not documentation.
        };
        // A script without an extension is read like a shell file.
        let script = !name.contains('.') && text.starts_with("#!");
        let Some(all_doc) = doc_kind(&name).or(script.then_some(false)) else {
            continue;
        };
        let rel = path.strip_prefix(root).unwrap_or(&path);
        let depth = rel.components().count().saturating_sub(1);
        let dir = path.parent().unwrap_or(root);
        let lines: Vec<(usize, String)> = if all_doc {
            text.lines()
                .enumerate()
                .map(|(k, l)| (k + 1, l.to_string()))
                .collect()
        } else {
            comments_of(&name, &text)
        };
        for (n, l) in lines {
            if let Some(why) = external_reference(&l, dir, depth) {
                problems.push(format!("{}:{n}: {why}", rel.display()));
            }
        }
    }
    problems.sort();
    Ok(problems)
}

/// Every rule; the error lists every violation.
pub fn tidy(root: &Path) -> Result<()> {
    let mut problems = check_dependencies(root)?;
    problems.extend(check_unused_dependencies(root)?);
    problems.extend(check_headers(root)?);
    problems.extend(check_external_references(root)?);
    if problems.is_empty() {
        Ok(())
    } else {
        bail!(
            "tidy found {} problem(s):\n  {}",
            problems.len(),
            problems.join("\n  ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_dependency_form() {
        let m = parse_manifest(
            r#"
[package]
name = "demo" # comment
[dependencies]
topology.workspace = true
robust-arith = { workspace = true, features = ["x"] }
local = { path = "../local" }
renamed = { package = "shadow-2d", path = "../shadow-2d" }
serde = "1"
[dependencies.tabled]
path = "../tabled"
[target.'cfg(unix)'.dependencies]
unixy = { path = "../unixy" }
[dev-dependencies]
umbra.workspace = true
"#,
        );
        assert_eq!(m.name.as_deref(), Some("demo"));
        let names: Vec<_> = m
            .deps
            .iter()
            .map(|d| {
                (
                    d.package.as_str(),
                    d.kind.as_str(),
                    d.workspace,
                    d.path.as_deref(),
                )
            })
            .collect();
        assert_eq!(
            names,
            vec![
                ("topology", "dependencies", true, None),
                ("robust-arith", "dependencies", true, None),
                ("local", "dependencies", false, Some("../local")),
                ("shadow-2d", "dependencies", false, Some("../shadow-2d")),
                ("serde", "dependencies", false, None),
                ("tabled", "dependencies", false, Some("../tabled")),
                ("unixy", "dependencies", false, Some("../unixy")),
                ("umbra", "dev-dependencies", true, None),
            ]
        );
    }

    /// The checks can fail: a scratch workspace with an upward dependency,
    /// an unknown crate and a file without a header.
    #[test]
    fn rejects_upward_dependencies_unknown_crates_and_missing_headers() -> Result<()> {
        let root = std::env::temp_dir().join(format!("umbra-tidy-{}", std::process::id()));
        let _ = fs::remove_dir_all(&root);
        let mk = |rel: &str, text: &str| -> Result<()> {
            let p = root.join(rel);
            if let Some(d) = p.parent() {
                fs::create_dir_all(d)?;
            }
            fs::write(p, text)?;
            Ok(())
        };
        mk(
            "Cargo.toml",
            "[workspace.dependencies]\nshadow-2d = { path = \"crates/shadow-2d\" }\ntopology = { path = \"crates/topology\" }\n",
        )?;
        mk(
            "crates/topology/Cargo.toml",
            "[package]\nname = \"topology\"\n[dependencies]\nshadow-2d.workspace = true\n[dev-dependencies]\nshadow-2d.workspace = true\n",
        )?;
        mk("crates/topology/src/lib.rs", "//! ok\n")?;
        mk(
            "crates/shadow-2d/Cargo.toml",
            "[package]\nname = \"shadow-2d\"\n[dependencies]\ntopology.workspace = true\n",
        )?;
        mk("crates/shadow-2d/src/lib.rs", "fn main() {}\n")?;
        mk(
            "crates/mystery/Cargo.toml",
            "[package]\nname = \"mystery\"\n",
        )?;
        mk("target/debug/build.rs", "no header but ignored\n")?;
        let deps = check_dependencies(&root)?;
        let headers = check_headers(&root)?;
        let _ = fs::remove_dir_all(&root);
        assert_eq!(deps.len(), 2, "{deps:?}");
        assert!(deps
            .iter()
            .any(|p| p.contains("'mystery' is not in the dependency table")));
        assert!(deps
            .iter()
            .any(|p| p.contains("'topology' has a dependency on 'shadow-2d'")));
        assert_eq!(headers.len(), 1, "{headers:?}");
        assert!(headers[0].contains("shadow-2d/src/lib.rs"));
        Ok(())
    }
    /// A scratch directory for one test, removed first.
    fn scratch(tag: &str) -> PathBuf {
        let root = std::env::temp_dir().join(format!("umbra-tidy-{tag}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&root);
        root
    }

    fn write(root: &Path, rel: &str, text: &str) -> Result<()> {
        let p = root.join(rel);
        if let Some(d) = p.parent() {
            fs::create_dir_all(d)?;
        }
        fs::write(p, text)?;
        Ok(())
    }

    #[test]
    fn the_lexer_separates_comments_from_strings_and_char_literals() {
        let (code, comments) = split_rust(
            "//! head\nlet a = \"// not a comment\"; // tail\nlet q = '\"'; let l: &'static str = r#\"x \" // y\"#;\n/* block\n /* nested */ */ /// doc\nfn f() {}\n",
        );
        assert!(code.contains("\"// not a comment\""));
        assert!(code.contains("r#\"x \" // y\"#"));
        assert!(code.contains("fn f() {}"));
        let texts: Vec<(usize, bool, &str)> = comments
            .iter()
            .map(|c| (c.line, c.doc, c.text.as_str()))
            .collect();
        assert_eq!(
            texts,
            vec![
                (1, true, " head"),
                (2, false, " tail"),
                (4, false, " block\n /* nested */ "),
                (5, true, " doc"),
            ]
        );
    }

    #[test]
    fn crate_names_count_only_as_path_roots() {
        assert!(names_crate("use num_traits::Zero;", "num_traits"));
        assert!(names_crate(
            "let x = rayon::current_num_threads();",
            "rayon"
        ));
        assert!(names_crate("use serde;", "serde"));
        assert!(names_crate("extern crate proptest;", "proptest"));
        assert!(!names_crate("use serde_json::json;", "serde"));
        assert!(!names_crate("use crate::topology::x;", "topology"));
        assert!(!names_crate("let topology = 1;", "topology"));
        assert!(!names_crate("my_rayon::x()", "rayon"));
    }

    /// The unused-dependency rule fires on a normal dependency, a
    /// dev-dependency and a workspace entry nobody takes, and not on a
    /// dependency named only in a doc test, through a rename or in a test.
    #[test]
    fn rejects_unused_dependencies() -> Result<()> {
        let root = scratch("unused");
        write(
            &root,
            "Cargo.toml",
            "[workspace]\nmembers = [\"a\"]\n[workspace.dependencies]\nsmallvec = \"1\"\nslotmap = \"1\"\nnum-traits = \"0.2\"\n",
        )?;
        write(
            &root,
            "a/Cargo.toml",
            "[package]\nname = \"a\"\n[dependencies]\nsmallvec.workspace = true\nrayon = \"1\"\nnum-traits.workspace = true\nalias = { package = \"serde\", version = \"1\" }\n[dev-dependencies]\nproptest = \"1\"\nnum-bigint = \"0.4\"\n",
        )?;
        write(
            &root,
            "a/src/lib.rs",
            "//! A.\n//!\n//! ```\n//! use rayon::prelude::*;\n//! ```\n// smallvec::SmallVec is only mentioned here.\nuse num_traits::Zero;\nuse alias::Serialize;\n",
        )?;
        write(&root, "a/tests/t.rs", "//! T.\nuse proptest::prelude::*;\n")?;
        let problems = check_unused_dependencies(&root)?;
        let _ = fs::remove_dir_all(&root);
        assert_eq!(problems.len(), 3, "{problems:?}");
        assert!(problems
            .iter()
            .any(|p| p.contains("dependency 'smallvec'") && p.starts_with("a/Cargo.toml")));
        assert!(problems
            .iter()
            .any(|p| p.contains("dev-dependency 'num-bigint'")));
        assert!(problems
            .iter()
            .any(|p| p.contains("[workspace.dependencies] 'slotmap' is taken by no member")));
        Ok(())
    }

    /// A crate under `crates/` may not take a dev-only crate as a normal
    /// dependency; as a dev-dependency it may.
    #[test]
    fn rejects_a_normal_dependency_on_a_dev_only_crate() -> Result<()> {
        let root = scratch("devonly");
        write(
            &root,
            "Cargo.toml",
            "[workspace.dependencies]\ntest-support = { path = \"crates/test-support\" }\n",
        )?;
        write(
            &root,
            "crates/test-support/Cargo.toml",
            "[package]\nname = \"test-support\"\n",
        )?;
        write(
            &root,
            "crates/topology/Cargo.toml",
            "[package]\nname = \"topology\"\n[dev-dependencies]\ntest-support.workspace = true\n",
        )?;
        write(
            &root,
            "crates/shadow-1d/Cargo.toml",
            "[package]\nname = \"shadow-1d\"\n[dependencies]\ntest-support.workspace = true\n",
        )?;
        let problems = check_dependencies(&root)?;
        let _ = fs::remove_dir_all(&root);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(problems[0]
            .contains("'shadow-1d' has a dependency on the dev-only crate 'test-support'"));
        Ok(())
    }

    /// The external-reference rule fires on each kind of reference, in
    /// Markdown, in Rust comments and in TOML comments, and not on paths
    /// that stay inside the repository or on string literals.
    #[test]
    fn rejects_docs_and_comments_pointing_outside_the_repository() -> Result<()> {
        let root = scratch("external");
        let design = concat!("DESIGN", ".md");
        let thesis = concat!("thesis", ".txt");
        write(
            &root,
            "docs/a.md",
            &format!("See [b](../README.md) and `docs/x.md`.\nRead {design} first.\n"),
        )?;
        write(&root, "docs/b.md", "The text: ../outside/x.\n")?;
        write(
            &root,
            "crates/x/src/lib.rs",
            &format!(
                "//! Module.\n// see {thesis}, section 4\nlet p = \"/work/data\"; // fine: ../../../README.md\n/* under /tmp/scratch */\n"
            ),
        )?;
        write(
            &root,
            "crates/x/Cargo.toml",
            "[dependencies]\ny = { path = \"../y\" } # from ../../../outside\n",
        )?;
        write(&root, "README.md", "Clone into /home/me/umbra.\n")?;
        write(
            &root,
            ".ci/run",
            "#!/usr/bin/env bash\necho /tmp/ok # logs go to /mnt/logs\n",
        )?;
        write(&root, ".git/notes.md", "See /work/x.\n")?;
        let problems = check_external_references(&root)?;
        let _ = fs::remove_dir_all(&root);
        let expect = [
            ".ci/run:2: points to the absolute path `/mnt/..`",
            "README.md:1: points to the absolute path `/home/..`",
            "crates/x/Cargo.toml:2: has the relative path `../../../outside`",
            "crates/x/src/lib.rs:2: names `thesis",
            "crates/x/src/lib.rs:4: points to the absolute path `/tmp/..`",
            "docs/a.md:2: names `DESIGN",
            "docs/b.md:1: has the relative path `../outside/x.`, which leads to nothing",
        ];
        assert_eq!(problems.len(), expect.len(), "{problems:?}");
        for (p, e) in problems.iter().zip(expect) {
            assert!(p.starts_with(e), "{p} / {e}");
        }
        Ok(())
    }
}
