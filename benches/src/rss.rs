//! The resident set's growth during an operation, as the kernel sees it
//! (Linux `/proc`): `VmRSS` before, the peak reset (`/proc/self/clear_refs`,
//! value 5), `VmHWM` after. It counts every allocation, the C++ peers'
//! included, and allocator retention; the memory columns of
//! `perf-table-3d` and `peak-memory-2d` are this measure.

/// A field of `/proc/self/status` in KiB (`None` off Linux or when the
/// field is missing).
fn status_kib(field: &str) -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/status").ok()?;
    text.lines()
        .find(|l| l.starts_with(field))?
        .split_whitespace()
        .nth(1)?
        .parse()
        .ok()
}

/// A measurement in progress: started by [`RssGrowth::start`], read by
/// [`RssGrowth::kib`].
#[derive(Clone, Copy, Debug)]
pub struct RssGrowth {
    base: u64,
}

impl RssGrowth {
    /// Reads the resident set now and resets the kernel's peak.
    pub fn start() -> Self {
        let base = status_kib("VmRSS:").unwrap_or(0);
        // Unavailable off Linux or in a restricted sandbox: the peak then
        // also covers what came before, an upper bound.
        let _ = std::fs::write("/proc/self/clear_refs", "5");
        RssGrowth { base }
    }

    /// The peak resident set since [`RssGrowth::start`] minus the resident
    /// set then (KiB; 0 where `/proc` is unavailable).
    pub fn kib(self) -> u64 {
        status_kib("VmHWM:").unwrap_or(0).saturating_sub(self.base)
    }
}
