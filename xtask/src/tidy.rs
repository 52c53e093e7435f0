//! `cargo xtask tidy`: the structural rules of the workspace.
//!
//! 1. Dependencies only point down the double pyramid (DESIGN.md, "The
//!    double pyramid and the crates"): a normal (or build) dependency of a
//!    crate under `crates/` on another workspace crate must be in the
//!    allowed table below. Dev-dependencies may point anywhere.
//! 2. Every `.rs` file of the repository (outside build output) starts with
//!    a `//!` header comment.
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
/// workspace crates (DESIGN.md table). A crate missing here is an error.
pub const ALLOWED: &[(&str, &[&str])] = &[
    ("robust-arith", &[]),
    ("topology", &["robust-arith"]),
    ("shadow-1d", &["topology", "robust-arith"]),
    ("shadow-2d", &["shadow-1d", "topology", "robust-arith"]),
    (
        "boolean-2d",
        &["shadow-2d", "shadow-1d", "topology", "robust-arith"],
    ),
    (
        "boolean-3d",
        &["shadow-2d", "shadow-1d", "topology", "robust-arith"],
    ),
    ("simplify-2d", &["shadow-1d", "topology", "robust-arith"]),
    (
        "smooth",
        &[
            "boolean-2d",
            "boolean-3d",
            "simplify-2d",
            "shadow-2d",
            "shadow-1d",
            "topology",
            "robust-arith",
        ],
    ),
    (
        "umbra",
        &[
            "smooth",
            "boolean-2d",
            "boolean-3d",
            "simplify-2d",
            "shadow-2d",
            "shadow-1d",
            "topology",
            "robust-arith",
        ],
    ),
    ("umbra-cli", &["umbra"]),
];

/// One dependency entry of a manifest.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dep {
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
                "crates/{}: crate '{name}' is not in the dependency table of DESIGN.md; add it to xtask/src/tidy.rs ALLOWED with its allowed dependencies",
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

/// Directories never scanned for `.rs` files: build output and VCS data.
fn skipped_dir(name: &str) -> bool {
    name.starts_with("target") || name.starts_with('.') || name == "node_modules"
}

/// The header rule: every `.rs` file not starting with `//!`.
pub fn check_headers(root: &Path) -> Result<Vec<String>> {
    let mut problems = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        let mut entries: Vec<_> = fs::read_dir(&dir)
            .with_context(|| format!("reading {}", dir.display()))?
            .collect::<std::io::Result<_>>()?;
        entries.sort_by_key(|e| e.file_name());
        for entry in entries {
            let path = entry.path();
            let name = entry.file_name().to_string_lossy().into_owned();
            let ty = entry.file_type()?;
            if ty.is_dir() {
                if !skipped_dir(&name) {
                    stack.push(path);
                }
            } else if ty.is_file() && name.ends_with(".rs") {
                let text = fs::read_to_string(&path)
                    .with_context(|| format!("reading {}", path.display()))?;
                if !text.starts_with("//!") {
                    let rel = path.strip_prefix(root).unwrap_or(&path);
                    problems.push(format!(
                        "{}: does not start with a `//!` header comment",
                        rel.display()
                    ));
                }
            }
        }
    }
    problems.sort();
    Ok(problems)
}

/// Both rules; the error lists every violation.
pub fn tidy(root: &Path) -> Result<()> {
    let mut problems = check_dependencies(root)?;
    problems.extend(check_headers(root)?);
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
}
