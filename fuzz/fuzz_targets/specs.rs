//! The JSON readers of `gam pose`, `gam hermite` and `gam interpolate` on arbitrary bytes
//! that parse as JSON, and the constructions they lead to: any result or a `CliError` is fine;
//! a panic, an abort, a hang or running out of memory is a finding. The work budget is
//! lowered so that one input stays within milliseconds.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: {
        // SAFETY: set once, before any other thread of the process reads the environment.
        unsafe { std::env::set_var("GAM_WORK_BUDGET", "1e5") };
    },
    |data: &[u8]| {
        let Ok(v) = serde_json::from_slice::<serde_json::Value>(data) else { return };
        let _ = gam::api::pose(&v);
        let _ = gam::api::hermite(&v, "spec");
        let _ = gam::api::interpolate(&v, "spec");
    }
);
