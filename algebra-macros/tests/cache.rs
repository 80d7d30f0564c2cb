//! The expansion cache end to end: the same declaration twice in one crate (module `g` in `a`
//! and in `b`), so the second expansion is read back from the entry the first one stored. Both
//! modules must compile and compute the same values, and the entry must exist where the cache
//! keeps it (`target/<profile>/gam-algebra-cache/`, beside the macro's library).

use algebra_core::rational::{Q, ratio};

mod a {
    algebra_macros::algebra! {
        /// 3D PGA with automatic types (tables) and straight-line kernels.
        pub mod g {
            metric builtin "pga3";
            types {
                Plane = grade 1;
                Point = grade 3;
                Motor = even;
            }
        }
    }
}

mod b {
    algebra_macros::algebra! {
        /// 3D PGA with automatic types (tables) and straight-line kernels.
        pub mod g {
            metric builtin "pga3";
            types {
                Plane = grade 1;
                Point = grade 3;
                Motor = even;
            }
        }
    }
}

/// Coefficients `k/3 - 1` for `k = seed, seed + 1, ...`.
fn coeffs(n: usize, seed: i64) -> Vec<Q> {
    (0..n as i64).map(|k| ratio((seed + 5 * k) % 7, 3) - ratio(1, 1)).collect()
}

#[test]
fn a_declaration_read_back_from_the_cache_computes_the_same_values() {
    let (m, p) = (coeffs(8, 1), coeffs(4, 2));
    let ma = a::g::Motor::<Q>::from_array(m.clone().try_into().unwrap());
    let pa = a::g::Point::<Q>::from_array(p.clone().try_into().unwrap());
    let mb = b::g::Motor::<Q>::from_array(m.try_into().unwrap());
    let pb = b::g::Point::<Q>::from_array(p.try_into().unwrap());
    assert_eq!(ma.apply(&pa).to_array(), mb.apply(&pb).to_array());
    assert_eq!((&ma * &pa).to_array(), (&mb * &pb).to_array());
    // an automatic type's table kernel
    let (oa, ob) = (&ma * &pa, &mb * &pb);
    assert_eq!((&oa * &ma).to_array(), (&ob * &mb).to_array());
    // and both against the runtime engine
    assert_eq!((&oa * &ma).to_multivector(), oa.to_multivector().gp(&ma.to_multivector()));
}

#[cfg(target_os = "linux")]
#[test]
fn the_entry_lives_beside_the_macro_library() {
    // this test binary is target/<profile>/deps/cache-HASH, as is the macro's library
    let exe = std::env::current_exe().unwrap();
    let dir = exe.parent().unwrap().parent().unwrap().join("gam-algebra-cache");
    if std::env::var_os("GAM_ALGEBRA_CACHE").is_some_and(|v| v == "off") {
        return;
    }
    let entries: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(entries.iter().any(|n| n.starts_with("g-") && n.ends_with(".rs")), "{entries:?}");
}
