//! The binary's logger: the engine reports its phases through the `log` crate
//! (e.g. the stroke driver's phases and timings at `debug`, every raw piece
//! and failed test at `trace`); `RUST_LOG` chooses the level (`error`, `warn`,
//! `info`, `debug`, `trace`, optionally as `lncert=debug`), and the lines go
//! to stderr. Without `RUST_LOG` nothing is logged.

use log::{Level, LevelFilter, Log, Metadata, Record};

struct Stderr;

impl Log for Stderr {
    fn enabled(&self, m: &Metadata) -> bool {
        m.level() <= log::max_level()
    }
    fn log(&self, r: &Record) {
        if self.enabled(r.metadata()) {
            eprintln!("[{} {}] {}", r.level(), r.target(), r.args());
        }
    }
    fn flush(&self) {}
}

/// The level named by `RUST_LOG` (its last `target=level` or `level` item).
fn level(spec: &str) -> Option<LevelFilter> {
    let item = spec.split(',').next_back()?.trim();
    let name = item.rsplit('=').next()?.trim();
    name.parse::<Level>().ok().map(|l| l.to_level_filter())
}

/// Installs the logger when `RUST_LOG` names a level.
pub fn init() {
    let Some(filter) = std::env::var("RUST_LOG").ok().as_deref().and_then(level) else {
        return;
    };
    static LOGGER: Stderr = Stderr;
    if log::set_logger(&LOGGER).is_ok() {
        log::set_max_level(filter);
    }
}

/// The process's peak resident memory in kB (`VmHWM` of
/// `/proc/self/status`, Linux), read only when `debug` is logged: the
/// figure `cli/benches/verifier_resources.rs` reads from `lncert verify`.
pub fn peak_memory_kb() -> Option<u64> {
    if log::max_level() < LevelFilter::Debug {
        return None;
    }
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.trim_start_matches("VmHWM:")
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rust_log_levels() {
        assert_eq!(level("debug"), Some(LevelFilter::Debug));
        assert_eq!(level("lncert=trace"), Some(LevelFilter::Trace));
        assert_eq!(level("warn,lncert=info"), Some(LevelFilter::Info));
        assert_eq!(level("loud"), None);
        assert_eq!(level(""), None);
    }
}
