//! Placeholder, replaced by the batch benchmark.
fn main() {}
