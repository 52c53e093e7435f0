//! The tidy rules as a test, so `cargo test --workspace` enforces them:
//! dependencies only point down the pyramid (DESIGN.md) and every `.rs`
//! file starts with a `//!` header.

#[test]
fn dependencies_point_down_the_pyramid() {
    let problems = xtask::tidy::check_dependencies(&xtask::tidy::workspace_root())
        .expect("manifests are readable");
    assert!(problems.is_empty(), "\n  {}", problems.join("\n  "));
}

#[test]
fn every_rust_file_has_a_header() {
    let problems =
        xtask::tidy::check_headers(&xtask::tidy::workspace_root()).expect("files are readable");
    assert!(problems.is_empty(), "\n  {}", problems.join("\n  "));
}
