//! Property tests of the ideal module (the sympy cross-checks are in
//! `algebra-core/tests/groebner_sympy.rs`).

use super::*;
use crate::Ring;
use proptest::prelude::*;

fn poly_from(coeffs: &[(i64, [u32; 3])]) -> Poly {
    let names = ["x", "y", "z"];
    Poly::from_terms(
        coeffs
            .iter()
            .map(|(c, e)| (Rational::from(*c), names.iter().zip(e).map(|(n, k)| (n.to_string(), *k)).collect())),
    )
}

fn arb_poly(max_terms: usize) -> impl Strategy<Value = Poly> {
    prop::collection::vec((-5i64..=5, [0u32..3, 0u32..3, 0u32..3]), 1..=max_terms).prop_map(|ts| poly_from(&ts))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// For random f, g and a random basis G = groebner(g_1, g_2): f*g_1 + h reduces to the
    /// normal form of h, and the normal form is unique (reducing twice changes nothing).
    #[test]
    fn multiples_of_the_ideal_reduce_away(
        f in arb_poly(3), g1 in arb_poly(3), g2 in arb_poly(3), h in arb_poly(4), lex in any::<bool>()
    ) {
        let order = if lex { MonomialOrder::Lex } else { MonomialOrder::GrevLex };
        let ring = PolyRing::new(["x", "y", "z"], order);
        let budget = Budget { time: Some(std::time::Duration::from_secs(5)), ..Budget::default() };
        let basis = match ring.groebner(&[g1.clone(), g2.clone()], &budget) {
            Ok(b) => b,
            Err(IdealError::Undecided { .. }) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        let nh = basis.normal_form(&h).unwrap();
        let lhs = f.clone() * g1.clone() + f.clone() * f.clone() * g2.clone() + h.clone();
        prop_assert_eq!(basis.normal_form(&lhs).unwrap(), nh.clone());
        prop_assert_eq!(basis.normal_form(&nh).unwrap(), nh.clone());
        prop_assert!(basis.contains(&g1).unwrap() && basis.contains(&g2).unwrap());
        // The division identity f = sum q_i g_i + r, checked by expanding.
        let d = ring.divide(&lhs, &[g1.clone(), g2.clone()], &budget).unwrap();
        let back = d.quotients[0].clone() * g1 + d.quotients[1].clone() * g2 + d.remainder;
        prop_assert_eq!(back, lhs);
    }
}

#[test]
fn budget_gives_undecided_not_a_hang() {
    let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
    let gens = [
        x.pow_u32(5) + y.pow_u32(4) + z.pow_u32(3) - Poly::one(),
        x.pow_u32(3) + y.pow_u32(3) + z.pow_u32(2) - Poly::one(),
        x.clone() * y.clone() * z.clone() - Poly::from_i64(2),
    ];
    let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::Lex);
    let tiny = Budget { max_basis: 3, ..Budget::default() };
    match ring.groebner(&gens, &tiny) {
        Err(IdealError::Undecided { limit: Limit::BasisSize, .. }) => {}
        other => panic!("expected undecided, got {other:?}"),
    }
    let no_time = Budget { time: Some(std::time::Duration::ZERO), ..Budget::default() };
    assert!(matches!(ring.groebner(&gens, &no_time), Err(IdealError::Undecided { limit: Limit::Time, .. })));
}

/// Degrees past the packed monomials' 32767 (16-bit exponent fields) are `Limit::Degree`,
/// wherever they would first be formed: in the input, in an S-polynomial (grevlex: the lcm
/// of `x^20000 y` and `x y^20000`), in a reduction step (lex: `x^2` reduced by
/// `x - y^20000` reaches `y^40000`), in the textbook division; up to the limit, exact.
#[test]
fn degrees_past_the_packed_fields_are_undecided() {
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let degree = |r: Result<_, IdealError>| matches!(r, Err(IdealError::Undecided { limit: Limit::Degree, .. }));
    let grevlex = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
    assert!(degree(grevlex.to_dense(&x.pow_u32(40_000)).map(|_| ())));
    assert!(degree(grevlex.groebner(&[x.pow_u32(32_768)], &Budget::default()).map(|_| ())));
    let g = grevlex.groebner(&[x.pow_u32(32_767) - y.clone()], &Budget::default()).unwrap();
    assert!(g.contains(&(Poly::from_i64(3) * x.pow_u32(32_767) - Poly::from_i64(3) * y.clone())).unwrap());
    assert!(!g.contains(&(x.pow_u32(32_766) - y.clone())).unwrap());
    let gens = [x.pow_u32(20_000) * y.clone() - Poly::one(), x.clone() * y.pow_u32(20_000) - Poly::one()];
    assert!(degree(grevlex.groebner(&gens, &Budget::default()).map(|_| ())));
    let lex = PolyRing::new(["x", "y"], MonomialOrder::Lex);
    let g = lex.groebner(&[x.clone() - y.pow_u32(20_000)], &Budget::default()).unwrap();
    assert!(degree(g.normal_form(&(x.clone() * x.clone())).map(|_| ())));
    assert_eq!(g.normal_form(&x).unwrap(), y.pow_u32(20_000));
    let d = lex.divide(&(x.clone() * x.clone()), &[x.clone() - y.pow_u32(20_000)], &Budget::default());
    assert!(degree(d.map(|_| ())));
    let e = grevlex.to_dense(&x.pow_u32(40_000)).unwrap_err();
    assert!(e.to_string().contains("degree limit") && e.to_string().contains("32767"), "{e}");
}

/// A computation runs in 8-bit exponent fields while its degrees stay within 127 and again in
/// 16-bit fields when one would pass it: an S-polynomial of degree 200 (the lcm of `x^100 y`
/// and `x y^100`) stops the narrow run with `Limit::Degree` and the basis comes from the wide
/// run; a basis of low degree stays narrow, and a target of degree 131 is reduced by it
/// repacked. The results themselves are checked against sympy's in `tests/groebner_sympy.rs`
/// (systems `binomial-past-127`, `target-past-127`); here, that each path is taken and agrees
/// with the other layout.
#[test]
fn narrow_fields_hand_over_to_wide_past_degree_127() {
    use order::Fields;
    let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
    let ring = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
    let gens = [x.pow_u32(100) * y.clone() - Poly::one(), x.clone() * y.pow_u32(100) - Poly::one()];
    let narrow = ring.with_fields(Fields::Narrow);
    assert!(matches!(
        narrow.groebner(&gens, &Budget::default()),
        Err(IdealError::Undecided { limit: Limit::Degree, .. })
    ));
    let g = ring.groebner(&gens, &Budget::default()).unwrap();
    assert_eq!((g.ring().fields(), g.ring() == &ring), (Fields::Wide, true));
    assert!(g.polys().iter().any(|p| p.to_string() == "x**99 - y**99"), "{:?}", g.polys());

    let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::GrevLex);
    let gens = [x.pow_u32(2) - y.clone() * z.clone(), y.pow_u32(2) - z.clone()];
    let g = ring.groebner(&gens, &Budget::default()).unwrap();
    assert_eq!(g.ring().fields(), Fields::Narrow);
    let target = x.pow_u32(131) + y.pow_u32(130) * z.clone() + x.clone() * y.clone();
    let wide = ring.with_fields(Fields::Wide).groebner_in(&gens, &mut Meter::new(&Budget::default())).unwrap();
    assert_eq!(wide.ring().fields(), Fields::Wide);
    assert_eq!(wide.polys(), g.polys());
    assert_eq!(wide, g);
    assert_eq!(g.normal_form(&target).unwrap(), wide.normal_form(&target).unwrap());
    // The textbook division by a Gröbner basis leaves the normal form (a third code path, over Q).
    let textbook = ring.divide(&target, &g.polys(), &Budget::default()).unwrap().remainder;
    assert_eq!(g.normal_form(&target).unwrap(), textbook);
}

#[test]
fn unknown_variables_and_inconsistent_systems() {
    let x = Poly::var("x");
    let ring = PolyRing::new(["x"], MonomialOrder::GrevLex);
    assert_eq!(ring.groebner(&[Poly::var("w")], &Budget::default()), Err(IdealError::UnknownVariable("w".into())));
    // x = 0 and x = 1 together: the unit ideal.
    let g = ring.groebner(&[x.clone(), x - Poly::one()], &Budget::default()).unwrap();
    assert!(g.is_unit());
    assert!(g.contains(&Poly::var("x").pow_u32(7)).unwrap());
    assert!(ring.groebner(&[], &Budget::default()).unwrap().is_empty());
}

#[test]
fn rabinowitsch_needs_the_nonvanishing_hypothesis() {
    // x^2 = x y with x != 0 gives x = y; without it, x = y is not in the ideal (x = 0 is a
    // solution with any y).
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let eq = x.clone() * x.clone() - x.clone() * y.clone();
    let claim = x.clone() - y.clone();
    let with = Hypotheses { equations: vec![eq.clone()], nonzero: vec![x.clone()] };
    let d = decide(std::slice::from_ref(&claim), &with, &Budget::default()).unwrap();
    assert!(d.holds && !d.inconsistent);
    let without = Hypotheses { equations: vec![eq], nonzero: vec![] };
    let d = decide(&[claim], &without, &Budget::default()).unwrap();
    assert!(!d.holds);
    assert_eq!(d.failures.len(), 1);
    // x != 0 and x = 0: inconsistent, everything holds.
    let bad = Hypotheses { equations: vec![x.clone()], nonzero: vec![x] };
    assert!(decide(&[y], &bad, &Budget::default()).unwrap().inconsistent);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The geobucket reduction against the merge reduction it continues (the previous engine's)
    /// and against the textbook division over Q (`PolyRing::divide`, a separate code path with
    /// rational coefficients): the same remainder, whether the work moves into buckets at once,
    /// after a few terms, or never. With the first-divisor rule all three take the same steps.
    #[test]
    fn geobucket_reduction_matches_merge_and_textbook_division(
        f in arb_poly(14), gs in prop::collection::vec(arb_poly(4), 1..4), lex in any::<bool>()
    ) {
        let order = if lex { MonomialOrder::Lex } else { MonomialOrder::GrevLex };
        let ring = PolyRing::new(["x", "y", "z"], order);
        let gs: Vec<Poly> = gs.into_iter().filter(|g| !g.is_exact_zero()).collect();
        let (fd, fden) = ring.to_dense(&f).unwrap();
        let ds: Vec<DPoly> = gs.iter().map(|g| ring.to_dense(g).unwrap().0).collect();
        let reducers: Vec<division::Reducer<'_>> = ds.iter().map(|d| division::Reducer::new(d, ring.fields())).collect();
        let run = |long: usize| {
            let mut meter = Meter::new(&Budget::default());
            let division::Reduced { r, s, .. } =
                division::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, long).unwrap();
            ring.to_poly(&r, &(s * Rational::from(&fden)))
        };
        let merged = run(usize::MAX);
        let textbook = ring.divide(&f, &gs, &Budget::default()).unwrap().remainder;
        prop_assert_eq!(&merged, &textbook);
        prop_assert_eq!(run(0), merged.clone());
        prop_assert_eq!(run(3), merged);
    }
}

/// Long reductions in one variable whose remainders are known in closed form: `x ≡ 1` modulo
/// `3x - 3` (the work keeps the content 6 of `f`, which the buckets shed every 16 steps) and
/// `x ≡ 2/3` modulo `3x - 2` (every step scales the work by 3). Both switch points and the
/// merges alone give `6·x0^40 + 6y`, with `x0` the root.
#[test]
fn long_reductions_shed_content_and_track_the_scale_exactly() {
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let ring = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
    let f = Poly::from_i64(6) * x.pow_u32(40) + Poly::from_i64(6) * y.clone();
    for (g, root) in [
        (Poly::from_i64(3) * x.clone() - Poly::from_i64(3), Rational::from(1)),
        (Poly::from_i64(3) * x.clone() - Poly::from_i64(2), Rational::from((2, 3))),
    ] {
        let expected = Poly::constant(Rational::from(6) * Rational::from(rug::ops::Pow::pow(&root, 40u32)))
            + Poly::from_i64(6) * y.clone();
        let (fd, fden) = ring.to_dense(&f).unwrap();
        let gd = ring.to_dense(&g).unwrap().0;
        let reducers = [division::Reducer::new(&gd, ring.fields())];
        for long in [0, 3, usize::MAX] {
            let mut meter = Meter::new(&Budget::default());
            let division::Reduced { r, s, .. } =
                division::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, long).unwrap();
            assert_eq!(ring.to_poly(&r, &(s * Rational::from(&fden))), expected, "switch at {long}, g = {g}");
        }
    }
}

/// The term budget stops a reduction in either representation with the documented error: the
/// work of `6·x^40 + 6y` modulo `3x - 2` holds two terms and its remainder grows to two, so a
/// budget of one term is exceeded at once, whether the work is merged or in geobuckets, over
/// GMP or in machine words.
#[test]
fn term_budget_stops_merged_and_bucketed_reductions() {
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let ring = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
    let f = Poly::from_i64(6) * x.pow_u32(40) + Poly::from_i64(6) * y;
    let g = Poly::from_i64(3) * x - Poly::from_i64(2);
    let (fd, gd) = (ring.to_dense(&f).unwrap().0, ring.to_dense(&g).unwrap().0);
    let reducers = [division::Reducer::new(&gd, ring.fields())];
    let tiny = Budget { max_terms: 1, ..Budget::default() };
    for long in [0, usize::MAX] {
        let mut meter = Meter::new(&tiny);
        match division::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, long) {
            Err(IdealError::Undecided { limit: Limit::Terms, .. }) => {}
            other => panic!("switch at {long}: expected the term limit, got {:?}", other.map(|r| r.r)),
        }
    }
    // The same in machine words: merges (steps in place or not) and word geobuckets.
    let ds = with_small(std::slice::from_ref(&gd));
    let reducers = small_reducers(&ds, ring.fields());
    for (long, in_place) in [(0, false), (usize::MAX, false), (usize::MAX, true)] {
        let mut meter = Meter::new(&tiny);
        match small::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, long, in_place) {
            Err(IdealError::Undecided { limit: Limit::Terms, .. }) => {}
            other => panic!("words, switch at {long}: expected the term limit, got {:?}", other.map(|r| r.r)),
        }
    }
}

/// Divisors with their machine-word coefficients (what the Gröbner engine's state keeps).
fn with_small(ds: &[DPoly]) -> Vec<(DPoly, Option<Vec<i64>>)> {
    ds.iter().map(|d| (d.clone(), small::small_coefs(d))).collect()
}

fn small_reducers(ds: &[(DPoly, Option<Vec<i64>>)], fields: order::Fields) -> Vec<division::Reducer<'_>> {
    ds.iter().map(|(d, s)| division::Reducer { small: s.as_deref(), ..division::Reducer::new(d, fields) }).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The machine-word reduction against the textbook division over Q (`PolyRing::divide`,
    /// rational coefficients, a separate code path), `f` scaled by 7^k (up to 7^24 > 2^67: some
    /// reductions start over GMP) and the divisors by 11^j (up to 11^18 < 2^63: every step
    /// multiplies the work by up to 11^j, so some reductions overflow the words after a step or
    /// a few, and some never do). The ring has 0 to 61 unused variables after `x, y, z` and
    /// 8- or 16-bit exponent fields, so that monomials take 2 to 17 words: every width the
    /// merges have a copy of (2-6) and the general one.
    #[test]
    fn machine_word_reduction_matches_textbook_division(
        f in arb_poly(14), gs in prop::collection::vec(arb_poly(4), 1..4), k in 0u32..=24, j in 0u32..=18,
        lex in any::<bool>(), pad in 0usize..6, narrow in any::<bool>()
    ) {
        let order = if lex { MonomialOrder::Lex } else { MonomialOrder::GrevLex };
        let names: Vec<String> = ["x", "y", "z"]
            .into_iter()
            .map(String::from)
            .chain((0..[0, 13, 21, 29, 37, 61][pad]).map(|i| format!("u{i}")))
            .collect();
        let ring = PolyRing::new(&names, order)
            .with_fields(if narrow { order::Fields::Narrow } else { order::Fields::Wide });
        let power = |b: u32, e: u32| Rational::from(rug::ops::Pow::pow(Integer::from(b), e));
        let gs: Vec<Poly> =
            gs.into_iter().filter(|g| !g.is_exact_zero()).map(|g| g.scale(&power(11, j))).collect();
        let f = f.scale(&power(7, k));
        let (fd, fden) = ring.to_dense(&f).unwrap();
        let ds: Vec<DPoly> = gs.iter().map(|g| ring.to_dense(g).unwrap().0).collect();
        let ds = with_small(&ds);
        let reducers = small_reducers(&ds, ring.fields());
        let textbook = ring.divide(&f, &gs, &Budget::default()).unwrap().remainder;
        // Merges until 256 terms (never, here), word geobuckets from the start or after 3 terms;
        // merge steps tried in place first (as for normal forms) or not.
        for (long, in_place) in [(division::LONG_WORK, false), (division::LONG_WORK, true), (0, false), (3, true)] {
            let mut meter = Meter::new(&Budget::default());
            let division::Reduced { r, s, .. } =
                small::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, long, in_place).unwrap();
            prop_assert_eq!(
                ring.to_poly(&r, &(s * Rational::from(&fden))), textbook.clone(), "switch at {}, in place {}", long, in_place
            );
        }
    }
}

/// The word geobuckets against the textbook division over Q on random reductions whose
/// coefficients pass 2^63 at different points, and each of the three ways of handing over to
/// the GMP buckets taken at least once (a leading coefficient that does not fit, a scaling of
/// the multipliers, a merge): divisors scaled by 11^j or with one coefficient near 2^62, the
/// work from the start in buckets. The rings take turns: 0 to 61 unused variables after
/// `x, y, z`, 8- or 16-bit fields (monomials of 2 to 17 words: each width the bucket merges
/// have a copy of, and the general one).
#[test]
fn word_geobuckets_hand_over_to_gmp_exactly() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let strategy = (arb_poly(14), prop::collection::vec(arb_poly(4), 1..4), 0u32..=18, 0u32..=3);
    small_bucket::HANDED_OVER.with(|h| h.set([0; 3]));
    let rings: Vec<PolyRing> = [0, 13, 21, 29, 37, 61]
        .into_iter()
        .flat_map(|pad| {
            let names: Vec<String> =
                ["x", "y", "z"].into_iter().map(String::from).chain((0..pad).map(|i| format!("u{i}"))).collect();
            let ring = PolyRing::new(&names, MonomialOrder::GrevLex);
            [ring.with_fields(order::Fields::Narrow), ring]
        })
        .collect();
    for case in 0..400 {
        let ring = &rings[case % rings.len()];
        let (f, gs, j, big) = strategy.new_tree(&mut runner).unwrap().current();
        let power = |b: u32, e: u32| Rational::from(rug::ops::Pow::pow(Integer::from(b), e));
        let near = Poly::constant(Rational::from((Integer::from(1) << 62u32) - 1));
        let gs: Vec<Poly> = gs
            .into_iter()
            .filter(|g| !g.is_exact_zero())
            .enumerate()
            .map(|(k, g)| {
                let g = g.scale(&power(11, j));
                // One divisor with a coefficient near 2^62 (`big` of 3 times).
                if k == 0 && big == 0 { g + near.clone() * Poly::var("z").pow_u32(3) } else { g }
            })
            .collect();
        let (fd, fden) = ring.to_dense(&f).unwrap();
        let ds: Vec<DPoly> = gs.iter().map(|g| ring.to_dense(g).unwrap().0).collect();
        let ds = with_small(&ds);
        let reducers = small_reducers(&ds, ring.fields());
        let textbook = ring.divide(&f, &gs, &Budget::default()).unwrap().remainder;
        let mut meter = Meter::new(&Budget::default());
        let division::Reduced { r, s, .. } =
            small::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, 0, false).unwrap();
        assert_eq!(ring.to_poly(&r, &(s * Rational::from(&fden))), textbook, "f = {f}, gs = {gs:?}");
    }
    // And one whose multipliers overflow for sure: 6·x^40 + 6y modulo 3x - 2 scales the work by
    // 3 at every step (3^40 > 2^63).
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let f = Poly::from_i64(6) * x.pow_u32(40) + Poly::from_i64(6) * y.clone();
    let g = Poly::from_i64(3) * x.clone() - Poly::from_i64(2);
    let ring = &rings[0];
    let (fd, fden) = ring.to_dense(&f).unwrap();
    let ds = with_small(&[ring.to_dense(&g).unwrap().0]);
    let reducers = small_reducers(&ds, ring.fields());
    let mut meter = Meter::new(&Budget::default());
    let division::Reduced { r, s, .. } =
        small::reduce_switching_at(fd, &reducers, ring.ord(), &mut meter, 0, false).unwrap();
    let textbook = ring.divide(&f, &[g], &Budget::default()).unwrap().remainder;
    assert_eq!(ring.to_poly(&r, &(s * Rational::from(&fden))), textbook);
    let handed = small_bucket::HANDED_OVER.with(|h| h.get());
    assert!(handed.iter().all(|&n| n > 0), "hand-overs by lead, scale, merge: {handed:?}");
}

/// Steps done where the work stands (normal forms), against the textbook division over Q on
/// random reductions in three variables (many monomials in common, so many steps only cancel or
/// update terms the work has), and both of the new paths taken: a step in place, and a merge
/// after steps in place that dropped the terms they left with the coefficient 0.
#[test]
fn steps_in_place_match_textbook_division() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let strategy = (arb_poly(20), prop::collection::vec(arb_poly(4), 1..4), 0u32..=2);
    small::IN_PLACE.with(|c| c.set([0; 2]));
    let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::GrevLex);
    for _ in 0..300 {
        let (h, gs, k) = strategy.new_tree(&mut runner).unwrap().current();
        let gs: Vec<Poly> = gs.into_iter().filter(|g| !g.is_exact_zero()).collect();
        // Mostly multiples of the divisors (as a claim that holds), plus a little of `h`.
        let mut f = h.clone() * Poly::from_i64(i64::from(k));
        for (n, g) in gs.iter().enumerate() {
            f = f + g.clone() * (h.clone() + Poly::var(["x", "y", "z"][n % 3]));
        }
        let (fd, fden) = ring.to_dense(&f).unwrap();
        let ds: Vec<DPoly> = gs.iter().map(|g| ring.to_dense(g).unwrap().0).collect();
        let ds = with_small(&ds);
        let reducers = small_reducers(&ds, ring.fields());
        let textbook = ring.divide(&f, &gs, &Budget::default()).unwrap().remainder;
        let mut meter = Meter::new(&Budget::default());
        let division::Reduced { r, s, .. } =
            small::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, division::LONG_WORK, true)
                .unwrap();
        assert_eq!(ring.to_poly(&r, &(s * Rational::from(&fden))), textbook, "f = {f}, gs = {gs:?}");
    }
    let taken = small::IN_PLACE.with(|c| c.get());
    assert!(taken.iter().all(|&n| n > 0), "steps in place, merges after them: {taken:?}");
}

/// The machine-word reduction past the words, in closed form: `6·x^40 + 6y` modulo `3x - 2`
/// scales the work by 3 at every step, so after about 40 steps its coefficients pass 2^63
/// (3^40 > 2^63) and the reduction continues over GMP from there; the remainder is
/// `6·(2/3)^40 + 6y` (by hand: `x ≡ 2/3`). Modulo `3x - 3` (`x ≡ 1`) the words never overflow.
#[test]
fn machine_word_reduction_overflows_into_gmp_exactly() {
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let ring = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
    let f = Poly::from_i64(6) * x.pow_u32(40) + Poly::from_i64(6) * y.clone();
    for (g, root) in [
        (Poly::from_i64(3) * x.clone() - Poly::from_i64(2), Rational::from((2, 3))),
        (Poly::from_i64(3) * x.clone() - Poly::from_i64(3), Rational::from(1)),
    ] {
        let expected = Poly::constant(Rational::from(6) * Rational::from(rug::ops::Pow::pow(&root, 40u32)))
            + Poly::from_i64(6) * y.clone();
        let (fd, fden) = ring.to_dense(&f).unwrap();
        let ds = with_small(&[ring.to_dense(&g).unwrap().0]);
        let reducers = small_reducers(&ds, ring.fields());
        // Word merges (steps in place or not), and word geobuckets from the start (whose
        // multipliers overflow instead).
        for (long, in_place) in [(division::LONG_WORK, false), (division::LONG_WORK, true), (0, false)] {
            let mut meter = Meter::new(&Budget::default());
            let division::Reduced { r, s, .. } =
                small::reduce_switching_at(fd.clone(), &reducers, ring.ord(), &mut meter, long, in_place).unwrap();
            assert_eq!(ring.to_poly(&r, &(s * Rational::from(&fden))), expected, "g = {g}, switch at {long}");
        }
    }
}

/// `d`'s monomials as plain exponent vectors `[degree, e_0, ..., e_{n-1}]` side by side.
fn plain(d: &DPoly, n: usize) -> Vec<u32> {
    (0..d.len())
        .flat_map(|t| {
            let m = d.mono(t);
            std::iter::once(m[0] as u32).chain((0..n).map(move |v| order::Fields::Wide.exponent(m, v)))
        })
        .collect()
}

#[test]
fn dense_form_follows_the_ring_variables_not_the_interned_ids() {
    // Interned in the order q_late, q_early; the ring lists them the other way round, so the
    // sorted id table and the variable order disagree.
    let (late, early) = (Poly::var("dense_q_late"), Poly::var("dense_q_early"));
    let ring = PolyRing::new(["dense_q_early", "dense_q_late"], MonomialOrder::GrevLex);
    let p = late.clone() * late.clone() * Poly::from_i64(3) + early.clone() * Poly::from_i64(5)
        - early.clone() * late.clone() * Poly::from_i64(7)
        + Poly::constant(Rational::from((1, 2)));
    let (d, den) = ring.to_dense(&p).unwrap();
    assert_eq!(den, 2);
    // Degree 2 first (early*late > late^2 in grevlex: smaller exponent of the last variable),
    // then early, then the constant; coefficients times the denominator 2.
    assert_eq!(plain(&d, 2), [2, 1, 1, 2, 0, 2, 1, 1, 0, 0, 0, 0]);
    assert_eq!(d.coefs, [Integer::from(-14), Integer::from(6), Integer::from(10), Integer::from(1)]);
    assert_eq!(ring.to_poly(&d, &Rational::from(den)), p);
    let other = PolyRing::new(["dense_q_early"], MonomialOrder::GrevLex);
    assert_eq!(other.to_dense(&late).unwrap_err(), IdealError::UnknownVariable("dense_q_late".into()));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The machine-word form of a polynomial is its dense form with the coefficients as words
    /// (integer coefficients that fit), and the normal forms taken through either agree.
    #[test]
    fn word_form_agrees_with_the_dense_form(f in arb_poly(6), g in arb_poly(3), big in any::<bool>()) {
        let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::GrevLex);
        let f = if big { f * Poly::constant(Rational::from(Integer::from(1) << 70u32)) } else { f };
        let (d, den) = ring.to_dense(&f).unwrap();
        match ring.to_words(&f).unwrap() {
            Some((exps, coefs)) => {
                prop_assert!(!big || d.is_zero());
                prop_assert_eq!(den, 1);
                prop_assert_eq!(exps, d.exps);
                prop_assert_eq!(coefs.iter().map(|&c| Integer::from(c)).collect::<Vec<_>>(), d.coefs);
            }
            None => prop_assert!(big && !d.is_zero()),
        }
        let half = f.clone() * Poly::constant(Rational::from((1, 2)));
        let halved_den = ring.to_dense(&half).unwrap().1;
        prop_assert!(halved_den == 1 || ring.to_words(&half).unwrap().is_none());
        // Normal forms: words path (f), GMP path (f/2, then doubled).
        let basis = ring.groebner(&[g], &Budget::default()).unwrap();
        let via_gmp = basis.normal_form(&half).unwrap() * Poly::from_i64(2);
        prop_assert_eq!(basis.normal_form(&f).unwrap(), via_gmp);
    }
}

#[test]
fn variable_lookup_by_table_and_by_binary_search_agree() {
    // Ids interned in the order below, lo, mid, 400 others, hi: the ring {lo, mid} has a short
    // id span (the table), {lo, hi} a long one (the binary search).
    let below = Poly::var("lookup_below");
    let (lo, mid) = (Poly::var("lookup_lo"), Poly::var("lookup_mid"));
    let gap: Vec<Poly> = (0..400).map(|k| Poly::var(&format!("lookup_gap_{k}"))).collect();
    let hi = Poly::var("lookup_hi");
    let short = PolyRing::new(["lookup_mid", "lookup_lo"], MonomialOrder::GrevLex);
    let long = PolyRing::new(["lookup_hi", "lookup_lo"], MonomialOrder::GrevLex);
    assert!(!short.vars.slot.is_empty() && long.vars.slot.is_empty());
    let p = lo.clone() * mid.clone() * mid.clone() + lo.clone();
    assert_eq!(plain(&short.to_dense(&p).unwrap().0, 2), [3, 2, 1, 1, 0, 1]);
    let q = lo.clone() * hi.clone() * hi.clone() + lo.clone();
    assert_eq!(plain(&long.to_dense(&q).unwrap().0, 2), [3, 2, 1, 1, 0, 1]);
    // {lo, gap_1}: mid and gap_0 fall inside the table's range, on empty slots.
    let holes = PolyRing::new(["lookup_lo", "lookup_gap_1"], MonomialOrder::GrevLex);
    assert!(!holes.vars.slot.is_empty());
    assert_eq!(plain(&holes.to_dense(&(gap[1].clone() * lo.clone())).unwrap().0, 2), [2, 1, 1]);
    let strangers = [(&short, &below), (&short, &gap[0]), (&short, &hi), (&long, &below), (&long, &mid)];
    for (ring, stranger) in strangers.into_iter().chain([(&holes, &mid), (&holes, &gap[0]), (&holes, &below)]) {
        let name = stranger.variables()[0].clone();
        assert_eq!(ring.to_dense(stranger).unwrap_err(), IdealError::UnknownVariable(name));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The chain criterion among new pairs, candidates sorted by lcm degree, against the same
    /// filter after a sort by the monomial order (the engine's before) and against its
    /// definition: a candidate is kept exactly when no other candidate's lcm properly divides its
    /// lcm and no candidate with the same lcm comes first (coprime first, then least `i`).
    #[test]
    fn chain_criterion_by_degree_keeps_the_same_pairs(
        ms in prop::collection::vec(([0u32..3, 0u32..3, 0u32..3], any::<bool>()), 0..24)
    ) {
        let packing = order::Packing::new(3, order::Fields::Wide);
        let w = packing.w;
        let mut lcms = Vec::new();
        let mut cands: Vec<groebner::Cand> = Vec::new();
        for (i, (e, coprime)) in ms.iter().enumerate() {
            let at = lcms.len();
            lcms.resize(at + w, 0);
            for (v, &k) in e.iter().enumerate() {
                packing.add_exponent(&mut lcms[at..at + w], v, k);
            }
            cands.push((i, at, *coprime, packing.fields.mask(&lcms[at..at + w])));
        }
        let lcm_of = |at: usize| &lcms[at..at + w];
        let mut fast = cands.clone();
        let kept = groebner::chain_among_new(&mut fast, &lcms, w, packing.fields);
        let mut fast: Vec<usize> = fast[..kept].iter().map(|c| c.0).collect();
        fast.sort_unstable();
        // The engine's before: sorted by the monomial order, coprime first, then the filter.
        let order = order::Order::new(MonomialOrder::GrevLex, packing.fields);
        let mut old = cands.clone();
        old.sort_by(|a, b| order.cmp(lcm_of(a.1), lcm_of(b.1)).then_with(|| b.2.cmp(&a.2)));
        let mut kept_old: Vec<groebner::Cand> = Vec::new();
        for c in old {
            if !kept_old.iter().any(|d| order.divides(lcm_of(d.1), lcm_of(c.1))) {
                kept_old.push(c);
            }
        }
        let mut old: Vec<usize> = kept_old.iter().map(|c| c.0).collect();
        old.sort_unstable();
        prop_assert_eq!(&fast, &old);
        // The definition.
        let first = |c: &groebner::Cand, d: &groebner::Cand| (!d.2, d.0) < (!c.2, c.0);
        let mut def: Vec<usize> = cands
            .iter()
            .filter(|c| {
                !cands.iter().any(|d| {
                    let (lc, ld) = (lcm_of(c.1), lcm_of(d.1));
                    (ld != lc && order.divides(ld, lc)) || (ld == lc && first(c, d))
                })
            })
            .map(|c| c.0)
            .collect();
        def.sort_unstable();
        prop_assert_eq!(fast, def);
    }
}

/// `sorted_terms` orders the terms by the packed grevlex comparison as the textbook definition
/// on plain exponent vectors does (degree, then the smaller exponent of the last variable where
/// they differ), over random polynomials in 3, 12 and 40 variables (sorted as fixed-size keys
/// or through an index) with one degree for most terms (the case where the comparison scans
/// furthest) and with degrees in the hundreds.
#[test]
fn packed_sort_is_grevlex() {
    let mut rng = crate::test_support::Xorshift(0x0DDB_1A5E_5BAD_5EED);
    for case in 0..300 {
        // 3, 12 and 40 variables: two and four words sorted as fixed-size keys, eleven by index
        let names: Vec<String> = (0..[3, 12, 40][case % 3]).map(|i| format!("v{i}")).collect();
        let ring = PolyRing::new(names.iter().map(String::as_str), MonomialOrder::GrevLex);
        let big = case % 10 < 3; // degrees in the hundreds: several words decide
        let terms = (0..60).map(|_| {
            let mut left = if big { 600 } else { 6 };
            let mono = names
                .iter()
                .filter_map(|n| {
                    let e = (rng.next_u64() % 3) as u32 * if big { 200 } else { 1 };
                    let e = e.min(left);
                    left -= e;
                    (e > 0).then(|| (n.clone(), e))
                })
                .collect();
            (Rational::from(1 + (rng.next_u64() % 7) as i64), mono)
        });
        let p = Poly::from_terms(terms);
        let w = ring.width();
        let t = ring.sorted_terms(&p).unwrap();
        assert_eq!(t.order.len(), p.term_count());
        let plain = |k: usize| -> Vec<u32> {
            let m = &t.exps[t.order[k] * w..(t.order[k] + 1) * w];
            (0..names.len()).map(|v| ring.fields().exponent(m, v)).collect()
        };
        for k in 1..t.order.len() {
            let (a, b) = (plain(k - 1), plain(k));
            let degree = |e: &[u32]| e.iter().sum::<u32>();
            let last_differing = a.iter().zip(&b).rev().find(|(x, y)| x != y).expect("distinct monomials");
            assert!(
                degree(&a) > degree(&b) || (degree(&a) == degree(&b) && last_differing.0 < last_differing.1),
                "case {case}: {a:?} before {b:?}"
            );
        }
    }
}

/// A reducer list handed back to its [`division::ReducerBuffer`] gives its allocation to the
/// next list (the engine builds one per S-pair), empty.
#[test]
fn a_kept_reducer_list_lends_its_buffer_to_the_next() {
    let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::GrevLex);
    let (p, _) = ring.to_dense(&poly_from(&[(2, [1, 0, 0]), (-3, [0, 1, 1])])).unwrap();
    let mut buffer = division::ReducerBuffer::default();
    let mut list = buffer.take();
    list.extend((0..40).map(|_| division::Reducer::new(&p, ring.fields())));
    let (capacity, at) = (list.capacity(), list.as_ptr() as usize);
    buffer.keep(list);
    let next = buffer.take();
    assert!(next.is_empty());
    assert_eq!((next.capacity(), next.as_ptr() as usize), (capacity, at));
}

/// Words made GMP integers from the pool of spent coefficients are the words, whatever the
/// pooled integers held (a 200-bit one, a negative one).
#[test]
fn integers_from_the_pool_are_the_words() {
    let big = Integer::from(1) << 200u32;
    division::recycle([vec![big, Integer::from(-7), Integer::from(0)]]);
    let words = [5i64, -(1 << 62), 0, i64::MAX, 1];
    let got = division::integers_from(&words);
    let want: Vec<Integer> = words.iter().map(|&x| Integer::from(x)).collect();
    assert_eq!(got, want);
}
