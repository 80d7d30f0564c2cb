//! `gam eval` on arbitrary text, in three algebras and three scalar types: any result or a
//! `CliError` is fine; a panic, an abort, a hang or running out of memory is a finding. The
//! work budget is lowered so that one input stays within milliseconds.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: {
        // SAFETY: set once, before any other thread of the process reads the environment.
        unsafe { std::env::set_var("GAM_WORK_BUDGET", "1e5") };
        unsafe { std::env::set_var("GAM_MEMORY_BUDGET", "1e7") };
    },
    |data: &[u8]| {
        let Ok(text) = std::str::from_utf8(data) else { return };
        for (algebra, basis, scalar) in [("g3", "blade", "rational"), ("cga-null", "product", "f64"), ("pga3", "blade", "poly")] {
            let _ = gam::api::eval(text, algebra, basis, scalar);
        }
    }
);
