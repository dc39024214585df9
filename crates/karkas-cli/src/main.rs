//! The `karkas` binary: the command line of the `karkas_cli` library, with mimalloc as its
//! allocator.

use std::process::ExitCode;

/// mimalloc keeps freed memory for the next allocation instead of returning it to the
/// kernel: large results (10^6 points and more) then skip the first-touch page faults that
/// cost more than the computation itself (BENCHMARKS.md, "Memory").
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    karkas_cli::run(std::env::args_os())
}
