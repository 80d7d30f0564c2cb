//! The worked examples of the main paper (Cross, Cripps and Mullineux 2022), once: the data the
//! docs, the `jaklic` example, the tests and the CLI tests all use.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`sec_4`] | Sec. 4, Figs. 3-5 | the quadrant: an additive cubic arc then a line |
//! | [`sec_5_1`] | Sec. 5.1 | Belta and Kumar's end conditions, one cubic segment (the `gam hermite` contract example) |
//! | [`sec_5_2`] | Sec. 5.2 | the shape factors `λ` and pseudoscalars `γ` |
//! | [`jaklic`] | Sec. 5.3, Fig. 10 | the motion of Jaklič et al. through nine precision poses |
//!
//! Printed values are kept as the paper prints them (strings with their decimals), so a test
//! compares by rounding, not by a tolerance chosen after the fact.
//!
//! ```
//! use motion::paper::sec_5_1;
//! use motion::spec::SpecKind;
//! let seg = sec_5_1::spec(SpecKind::Additive, sec_5_1::PRINTED_ANGLE).segment()?;
//! assert_eq!(format!("{:.3}", seg.control_poses()[1].e12), sec_5_1::ADDITIVE[0][1]);
//! # Ok::<(), motion::spec::SpecError>(())
//! ```

/// The blade names of the 8 components of a pose, in the order of the printed arrays.
pub const BLADES: [&str; 8] = ["1", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "e123inf"];

/// `x` printed to as many decimals as `printed` has equals `printed` (`-0.000` counts as
/// `0.000`): how every printed value of this module is compared.
///
/// ```
/// assert!(motion::paper::rounds_to(0.55749, "0.557"));
/// assert!(motion::paper::rounds_to(-0.0001, "0.000"));
/// assert!(!motion::paper::rounds_to(0.5576, "0.557"));
/// ```
pub fn rounds_to(x: f64, printed: &str) -> bool {
    let decimals = printed.split('.').nth(1).map_or(0, str::len);
    let s = format!("{x:.decimals$}");
    s == printed
        || s.strip_prefix('-').is_some_and(|rest| rest == printed && rest.chars().all(|c| c == '0' || c == '.'))
}

/// The blade names of the components of `c` (blade order) that do not round to `printed`.
///
/// ```
/// let c = [1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// let printed = ["1.000", "0.499", "0.000", "0.000", "0.000", "0.000", "0.000", "0.000"];
/// assert_eq!(motion::paper::mismatches(&c, &printed), ["e12"]);
/// ```
pub fn mismatches(c: &[f64; 8], printed: &[&str; 8]) -> Vec<&'static str> {
    c.iter().zip(printed).zip(BLADES).filter(|((x, p), _)| !rounds_to(**x, p)).map(|(_, b)| b).collect()
}

/// Sec. 4: a block turned a quarter turn about e3 while its centre runs along a quadrant of the
/// circle of radius 4 about (4, 0, 0) (an additive cubic on `[0, 1]`), then a translation along
/// a line (an additive cubic on `[1, 2]`).
pub mod sec_4 {
    use crate::{AdditiveBezier, Motor, Pose};

    fn pose(c: [f64; 8]) -> Pose<f64> {
        Pose::from_motor(Motor::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]))
    }

    /// `U_0..U_3` of the arc exactly as printed (4 decimals).
    ///
    /// ```
    /// assert_eq!(motion::paper::sec_4::printed_arc()[1].scalar, 0.8047);
    /// ```
    #[allow(clippy::approx_constant)] // the paper's printed values
    pub fn printed_arc() -> Vec<Pose<f64>> {
        vec![
            pose([0.7071, 0.7071, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
            pose([0.8047, 0.4714, 0.0, 0.0, 0.6667, 0.6667, 0.0, 0.0]),
            pose([0.9024, 0.2357, 0.0, 0.0, 1.3333, 1.3333, 0.0, 0.0]),
            pose([1.0, 0.0, 0.0, 0.0, 2.0, 2.0, 0.0, 0.0]),
        ]
    }

    /// The exact poses the printed ones round: `U_0 = (1 + e12)/√2` (a quarter turn about e3),
    /// `U_3 = 1 + 2e1inf + 2e2inf` (the translation by (4, 4, 0)), and `U_1, U_2` on the line
    /// between them: the cubic is the linear motion `(1 - t)U_0 + tU_3` degree-elevated twice.
    ///
    /// ```
    /// let e = motion::paper::sec_4::exact_arc();
    /// assert_eq!(e[3].e1inf, 2.0);
    /// ```
    pub fn exact_arc() -> Vec<Pose<f64>> {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let u0 = pose([h, h, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let u3 = pose([1.0, 0.0, 0.0, 0.0, 2.0, 2.0, 0.0, 0.0]);
        match AdditiveBezier::new(vec![u0, u3]) {
            Ok(b) => b.elevated().elevated().poses().to_vec(),
            Err(_) => unreachable!("two control poses make a Bezier motion"),
        }
    }

    /// `V_0..V_3` of the line exactly as printed (translations by `(2x, 4, 0)`).
    ///
    /// ```
    /// assert_eq!(motion::paper::sec_4::printed_line()[3].e1inf, 5.1416);
    /// ```
    #[allow(clippy::approx_constant)] // the paper's printed values
    pub fn printed_line() -> Vec<Pose<f64>> {
        [2.0, 3.0472, 4.0944, 5.1416].map(|x| pose([1.0, 0.0, 0.0, 0.0, x, 2.0, 0.0, 0.0])).to_vec()
    }

    /// The printed `Ψ(1)` at the end of the arc: `0.5858 - 1.4142 e12 + 5.6569 e2inf`
    /// (scalar, e12, e2inf).
    ///
    /// ```
    /// assert_eq!(motion::paper::sec_4::PRINTED_PSI_END_OF_ARC[2], 5.6569);
    /// ```
    #[allow(clippy::approx_constant)] // the paper's printed values
    pub const PRINTED_PSI_END_OF_ARC: [f64; 3] = [0.5858, -1.4142, 5.6569];
}

/// Sec. 5.1 (Belta and Kumar's end conditions): one cubic segment, both kinds, `λ = 1`,
/// `γ = 0`. This is also the example spec of the `gam hermite` contract (shared/cli.md).
pub mod sec_5_1 {
    use crate::EndCondition;
    use crate::spec::{EndSpec, HermiteSpec, SpecKind};

    /// The printed end angle `θ3 = 1.959` (itself rounded: exactly the angles in
    /// `[1.9591014, 1.9591494]`, e.g. 112.25°, reproduce all printed values).
    pub const PRINTED_ANGLE: f64 = 1.959;
    /// The end axis `(1, 2, 3)` (normalised by the constructors).
    pub const AXIS: [f64; 3] = [1.0, 2.0, 3.0];
    /// `S0 = 1`, printed.
    pub const S0: [&str; 8] = ["1.000", "0.000", "0.000", "0.000", "0.000", "0.000", "0.000", "0.000"];
    /// `S3`, printed.
    pub const S3: [&str; 8] = ["0.557", "0.666", "-0.444", "0.222", "2.895", "1.456", "4.010", "7.101"];
    /// Multiplicative `[S1, S2]`, printed.
    pub const MULTIPLICATIVE: [[&str; 8]; 2] = [
        ["0.812", "0.468", "-0.312", "0.156", "0.147", "0.138", "0.129", "0.156"],
        ["0.763", "0.413", "-0.497", "-0.013", "1.683", "1.508", "6.308", "4.363"],
    ];
    /// Additive `[S1, S2]`, printed.
    pub const ADDITIVE: [[&str; 8]; 2] = [
        ["1.000", "0.500", "-0.333", "0.167", "0.167", "0.167", "0.167", "0.000"],
        ["0.816", "0.462", "-0.536", "-0.001", "1.934", "1.764", "6.877", "4.707"],
    ];

    /// The end conditions in the spec format, with end angle `theta3` and end axis `axis3`.
    ///
    /// ```
    /// let (a, b) = motion::paper::sec_5_1::end_specs(1.959, motion::paper::sec_5_1::AXIS);
    /// assert_eq!((a.velocity, b.position), ([1.0, 1.0, 1.0], [8.0, 10.0, 12.0]));
    /// ```
    pub fn end_specs(theta3: f64, axis3: [f64; 3]) -> (EndSpec, EndSpec) {
        let a = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [1.0, 1.0, 1.0], [1.0, 2.0, 3.0]);
        let b = EndSpec::new([8.0, 10.0, 12.0], axis3, theta3, [1.0, 5.0, 3.0], [2.0, 1.0, 1.0]);
        (a, b)
    }

    /// The end conditions with end angle `theta3` and end axis `axis3`.
    ///
    /// ```
    /// let (a, _) = motion::paper::sec_5_1::end_conditions(1.959, motion::paper::sec_5_1::AXIS);
    /// assert_eq!(a.velocity_bivector().e12, 3.0); // Ω0 = (1, 2, 3): ν0 = 3 e12 - 2 e13 + e23 + ...
    /// ```
    pub fn end_conditions(theta3: f64, axis3: [f64; 3]) -> (EndCondition<f64>, EndCondition<f64>) {
        let (a, b) = end_specs(theta3, axis3);
        let cond = |e: &EndSpec, name| match e.end_condition(name) {
            Ok((c, _)) => c,
            Err(_) => unreachable!("the Sec. 5.1 end conditions are valid"),
        };
        (cond(&a, "start"), cond(&b, "end"))
    }

    /// The `gam hermite` spec of Sec. 5.1 (degree 3) with end angle `theta3`.
    ///
    /// ```
    /// use motion::{paper::sec_5_1, spec::SpecKind};
    /// assert_eq!(sec_5_1::spec(SpecKind::Multiplicative, 1.959).end.angle, 1.959);
    /// ```
    pub fn spec(kind: SpecKind, theta3: f64) -> HermiteSpec {
        let (a, b) = end_specs(theta3, AXIS);
        HermiteSpec::new(kind, 3, a, b)
    }
}

/// Sec. 5.2: shape factors and pseudoscalars, `γ0 = ½ + ½ω`, `γ3 = 1 - ½ω`, `λ = 1` or `4`.
pub mod sec_5_2 {
    use crate::spec::{EndSpec, HermiteSpec, SpecKind};
    use crate::{EndCondition, Pseudoscalar};
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_8};

    /// `[α, β]` of `γ0`.
    pub const GAMMA0: [f64; 2] = [0.5, 0.5];
    /// `[α, β]` of `γ3`.
    pub const GAMMA3: [f64; 2] = [1.0, -0.5];
    /// The two shape factors of the printed tables (index 0 and 1 of the arrays below).
    pub const LAMBDAS: [f64; 2] = [1.0, 4.0];
    /// `S3`, printed.
    pub const S3: [&str; 8] = ["0.707", "0.000", "0.000", "-0.707", "0.000", "3.536", "3.536", "0.000"];
    /// `ν0`, printed.
    pub const NU0: [&str; 8] = ["0.000", "0.000", "0.000", "-0.785", "0.000", "0.000", "8.000", "0.000"];
    /// `ν3`, printed.
    pub const NU3: [&str; 8] = ["0.000", "0.000", "0.000", "0.393", "0.000", "4.000", "-3.927", "0.000"];
    /// Multiplicative `[S1, S2]` for `λ = 1` and `λ = 4` (both ends), printed.
    pub const MULTIPLICATIVE: [[[&str; 8]; 2]; 2] = [
        [
            ["1.078", "0.000", "0.000", "-0.142", "0.012", "0.000", "1.445", "0.090"],
            ["0.558", "0.000", "0.000", "-0.636", "0.053", "2.392", "2.783", "0.047"],
        ],
        [
            ["1.209", "0.000", "0.000", "-0.698", "0.233", "0.000", "7.108", "0.403"],
            ["0.257", "0.000", "0.000", "-0.445", "0.148", "0.326", "1.266", "0.086"],
        ],
    ];
    /// Additive `[S1, S2]` for `λ = 1` and `λ = 4` (both ends), printed.
    pub const ADDITIVE: [[[&str; 8]; 2]; 2] = [
        [
            ["1.083", "0.000", "0.000", "-0.131", "0.000", "0.000", "1.333", "0.083"],
            ["0.543", "0.000", "0.000", "-0.636", "0.059", "2.243", "2.706", "0.059"],
        ],
        [
            ["1.333", "0.000", "0.000", "-0.524", "0.000", "0.000", "5.333", "0.333"],
            ["0.051", "0.000", "0.000", "-0.421", "0.236", "-1.633", "0.218", "0.236"],
        ],
    ];

    /// The end conditions in the spec format, with shape factors `lambda0`, `lambda3` and the
    /// paper's `γ0`, `γ3`.
    ///
    /// ```
    /// let (a, b) = motion::paper::sec_5_2::end_specs(4.0, 1.0);
    /// assert_eq!((a.shape, a.gamma, b.gamma), (4.0, [0.5, 0.5], [1.0, -0.5]));
    /// ```
    pub fn end_specs(lambda0: f64, lambda3: f64) -> (EndSpec, EndSpec) {
        let a = EndSpec::new([0.0; 3], [1.0, 0.0, 0.0], 0.0, [0.0, 0.0, 8.0], [-FRAC_PI_4, 0.0, 0.0]);
        let b = EndSpec::new([0.0, 10.0, 0.0], [1.0, 0.0, 0.0], -FRAC_PI_2, [0.0, 4.0, 0.0], [FRAC_PI_8, 0.0, 0.0]);
        (a.shaped(lambda0, GAMMA0), b.shaped(lambda3, GAMMA3))
    }

    /// The end conditions (poses, positions, velocities, angular velocities).
    ///
    /// ```
    /// let (a, _) = motion::paper::sec_5_2::end_conditions();
    /// assert_eq!(a.velocity_bivector().e3inf, 8.0);
    /// ```
    pub fn end_conditions() -> (EndCondition<f64>, EndCondition<f64>) {
        let (a, b) = end_specs(1.0, 1.0);
        let cond = |e: &EndSpec, name| match e.end_condition(name) {
            Ok((c, _)) => c,
            Err(_) => unreachable!("the Sec. 5.2 end conditions are valid"),
        };
        (cond(&a, "start"), cond(&b, "end"))
    }

    /// `[γ0, γ3]`.
    ///
    /// ```
    /// assert_eq!(motion::paper::sec_5_2::gammas()[1].clone(), motion::Pseudoscalar::new(1.0, -0.5));
    /// ```
    pub fn gammas() -> [Pseudoscalar<f64>; 2] {
        [GAMMA0, GAMMA3].map(|g| Pseudoscalar::new(g[0], g[1]))
    }

    /// The `gam hermite` spec of Sec. 5.2 (degree 3) with shape factors `lambda0`, `lambda3`.
    ///
    /// ```
    /// use motion::{paper::sec_5_2, spec::SpecKind};
    /// assert_eq!(sec_5_2::spec(SpecKind::Additive, 4.0, 4.0).start.shape, 4.0);
    /// ```
    pub fn spec(kind: SpecKind, lambda0: f64, lambda3: f64) -> HermiteSpec {
        let (a, b) = end_specs(lambda0, lambda3);
        HermiteSpec::new(kind, 3, a, b)
    }
}

/// Sec. 5.3: the motion of Jaklič et al. The reference point follows
/// `c(t) = 3 ln(t+1) cos t e1 + 3 ln(t+1) sin t e2 + 3(t+1) e3`, and the body turns by the
/// (non-unit) quaternion `q(t) = t + [t + cos(πt/4)] e23 + [sin(πt/4)] e31 + [cos(πt/10)] e12`.
/// The precision pose is `S(t) = R(t) T(c(t))` with `R = q/|q|`; the velocity of the reference
/// point is `c'(t)` and the angular velocity `Ω(t)` is read off `2 R⁻¹ R' = Ω e123`, both by
/// dual numbers ([`algebra_core::Jet`]). Precision poses at `t = 1, ..., 9`.
pub mod jaklic {
    use crate::hermite::{self, AnyHermiteSegment, HermiteShapes};
    use crate::joins::JoinError;
    use crate::{EndCondition, MotionError, Motor, Pose, SegmentKind, Shape};
    use algebra_core::{Jet, Real};

    /// The reference-point path `c(t)`.
    ///
    /// ```
    /// let c = motion::paper::jaklic::path(&0.0);
    /// assert_eq!(c, [0.0, 0.0, 3.0]);
    /// ```
    pub fn path<T: Real>(t: &T) -> [T; 3] {
        let t1 = t.add_ref(&T::one());
        let r = Real::ln(&t1).mul_ref(&T::from_i64(3));
        [r.mul_ref(&Real::cos(t)), r.mul_ref(&Real::sin(t)), t1.mul_ref(&T::from_i64(3))]
    }

    /// The rotation quaternion `q(t)` as an element of G_{123inf}^+ (not unitary).
    ///
    /// ```
    /// let q = motion::paper::jaklic::quaternion(&0.0);
    /// assert_eq!((q.scalar, q.e23, q.e12), (0.0, 1.0, 1.0));
    /// ```
    pub fn quaternion<T: Real>(t: &T) -> Pose<T> {
        let quarter = t.mul_ref(&T::pi()).mul_ref(&T::from_ratio(1, 4));
        let tenth = t.mul_ref(&T::pi()).mul_ref(&T::from_ratio(1, 10));
        let e23 = t.add_ref(&Real::cos(&quarter));
        let e31 = Real::sin(&quarter);
        let e12 = Real::cos(&tenth);
        let z = T::zero;
        Pose::from_motor(Motor::new(t.clone(), e12, e31.neg_ref(), e23, z(), z(), z(), z()))
    }

    /// The precision pose `S(t) = R(t) T(c(t))` (over dual numbers, `t + ε` gives `S'(t)`).
    /// Fails only where `q(t) = 0` (never for `t > 0`).
    ///
    /// ```
    /// let s = motion::paper::jaklic::pose(&1.0)?;
    /// assert!(s.is_unitary(&1e-14));
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn pose<T: Real>(t: &T) -> Result<Pose<T>, MotionError> {
        let rotor = quaternion(t).unitize()?;
        Ok(&rotor * &Pose::translation(&path(t)))
    }

    /// The end condition at `t`: `S(t)`, `c(t)`, `c'(t)` and `Ω(t)` from `2 R⁻¹ R' = Ω e123`.
    ///
    /// ```
    /// let c = motion::paper::jaklic::end_condition(2.0)?;
    /// assert_eq!(c.position, motion::paper::jaklic::path(&2.0));
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn end_condition(t: f64) -> Result<EndCondition<f64>, MotionError> {
        let td = Jet::variable(t);
        let rotor = quaternion(&td).unitize()?;
        let re = |x: &Jet<f64>| x.re;
        let eps = |x: &Jet<f64>| x.eps;
        let (r, dr) = (rotor.map_scalar(&re), rotor.map_scalar(&eps));
        let w = (r.try_inverse()? * dr).scale(&2.0);
        let omega = [w.e23, -w.e13, w.e12];
        let c = path(&td);
        Ok(EndCondition::new(pose(&t)?, c.clone().map(|x| x.re), c.map(|x| x.eps), omega))
    }

    /// The nine precision poses at `t = 1, ..., 9`.
    ///
    /// ```
    /// assert_eq!(motion::paper::jaklic::precision_poses()?.len(), 9);
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn precision_poses() -> Result<Vec<EndCondition<f64>>, MotionError> {
        (1..=9).map(|t| end_condition(f64::from(t))).collect()
    }

    /// The eight cubic segments of Fig. 10 with a common shape factor `lambda` (`γ = 0`).
    ///
    /// ```
    /// let segs = motion::paper::jaklic::segments(motion::SegmentKind::Additive, 1.5)?;
    /// assert_eq!(segs.len(), 8);
    /// # Ok::<(), motion::joins::JoinError>(())
    /// ```
    pub fn segments(kind: SegmentKind, lambda: f64) -> Result<Vec<AnyHermiteSegment<f64>>, JoinError> {
        hermite::hermite(kind, 3, &precision_poses()?, &HermiteShapes::Common(Shape::factor(lambda)))
    }
}
