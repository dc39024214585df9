//! Benchmarks of karkas live in `benches/`.
