//! Counts in headers never drive allocations: files whose header claims
//! billions of triangles, vertices or faces are refused using a few
//! kilobytes of heap, measured by a counting global allocator. One test in
//! its own binary, so no other test's allocations are counted.

use peak_alloc::PeakAlloc;
use umbra::{parse_off, parse_ply, parse_stl};

#[global_allocator]
static HEAP: PeakAlloc = PeakAlloc;

/// The heap peak above the current use while `f` runs.
fn peak_of(f: impl FnOnce() -> String) -> (usize, String) {
    let before = HEAP.current_usage();
    HEAP.reset_peak_usage();
    let message = f();
    (HEAP.peak_usage().saturating_sub(before), message)
}

/// A reader run on one hostile file, returning its message.
type Reader = Box<dyn Fn() -> String>;

#[test]
fn huge_counts_cost_no_memory() {
    let mut stl = vec![0u8; 84 + 50 * 3];
    stl[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let ply_binary = b"ply\nformat binary_big_endian 1.0\nelement vertex 4294967295\nproperty double x\nproperty double y\nproperty double z\nelement face 4294967295\nproperty list uint int vertex_indices\nend_header\n\0\0\0\0\0\0\0\0".to_vec();
    let ply_ascii = b"ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty double x\nproperty double y\nproperty double z\nend_header\n0 0 0\n".to_vec();
    let off = "OFF\n2147483647 2147483647 0\n0 0 0\n1 0 0\n";
    let cases: Vec<(&str, Reader)> = vec![
        (
            "stl",
            Box::new(move || parse_stl(&stl, "h.stl").unwrap_err().to_string()),
        ),
        (
            "ply binary",
            Box::new(move || parse_ply(&ply_binary, "h.ply").unwrap_err().to_string()),
        ),
        (
            "ply ascii",
            Box::new(move || parse_ply(&ply_ascii, "h.ply").unwrap_err().to_string()),
        ),
        (
            "off",
            Box::new(move || parse_off(off, "h.off").unwrap_err().to_string()),
        ),
    ];
    for (name, f) in cases {
        let (peak, message) = peak_of(f);
        assert!(message.contains("h."), "{name}: {message}");
        assert!(
            peak < 64 * 1024,
            "{name}: {peak} bytes of heap for {message}"
        );
    }
}
