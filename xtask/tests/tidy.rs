//! The tidy rules as a test, so `cargo test` enforces them: dependencies
//! only point down the pyramid (`docs/ARCHITECTURE.md`), every declared
//! dependency is used, every `.rs` file starts with a `//!` header, and no
//! doc or comment points outside the repository.

#[test]
fn dependencies_point_down_the_pyramid() {
    let problems = xtask::tidy::check_dependencies(&xtask::tidy::workspace_root())
        .expect("manifests are readable");
    assert!(problems.is_empty(), "\n  {}", problems.join("\n  "));
}

#[test]
fn every_declared_dependency_is_used() {
    let problems = xtask::tidy::check_unused_dependencies(&xtask::tidy::workspace_root())
        .expect("manifests and sources are readable");
    assert!(problems.is_empty(), "\n  {}", problems.join("\n  "));
}

#[test]
fn every_rust_file_has_a_header() {
    let problems =
        xtask::tidy::check_headers(&xtask::tidy::workspace_root()).expect("files are readable");
    assert!(problems.is_empty(), "\n  {}", problems.join("\n  "));
}

#[test]
fn no_doc_or_comment_points_outside_the_repository() {
    let problems = xtask::tidy::check_external_references(&xtask::tidy::workspace_root())
        .expect("files are readable");
    assert!(problems.is_empty(), "\n  {}", problems.join("\n  "));
}
