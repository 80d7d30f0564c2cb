//! The motion crate's integration tests: poses, motions, velocities, Jüttler's constructions.
//!
//! One test binary for the whole directory: each file is a module of it. One binary links once
//! (instead of once per file) and its tests share the test threads, so `cargo test` keeps both
//! cores busy instead of running many small binaries one after the other (issue 29).
//! `cargo test -p motion --test all -- MODULE::` runs one file's tests; a new file in this directory
//! must be added below (`all_modules::every_test_file_is_a_module` fails otherwise).

mod common;
mod juttler_common;

#[cfg(all(feature = "parallel", feature = "lanes"))]
mod batch;
mod bezier;
mod bezier_stability;
mod branch_free_lanes;
mod direct_paths;
mod edge_scale;
mod exact_poly;
mod exact_velocity;
mod exp_log;
mod finiteness;
mod hermite;
mod interpolation;
mod joins;
mod juttler_additive_trajectory;
mod juttler_bspline;
mod juttler_interpolation;
mod juttler_minimal;
mod juttler_parametrisation;
mod juttler_projective;
mod juttler_q_motion;
mod juttler_spline;
mod juttler_surface;
mod juttler_trajectory;
mod juttler_trt;
mod key_pose_scaling;
mod nalgebra_conv;
mod overflow_safe;
mod pose;
mod quaternion;
mod repr;
#[cfg(feature = "serde")]
mod schema;
mod trajectory;
mod unit_pose;
mod velocity;
mod wareham_lasenby;

#[path = "../../tests/support/all_modules.rs"]
mod all_modules;
