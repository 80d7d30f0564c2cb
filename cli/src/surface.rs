//! `gam surface [--json] [--scalar S] SPEC.json --curve CURVE.json`: the kinematic (sweep)
//! surface of a rational Bézier curve of the moving body under the motion of a `gam
//! interpolate` spec (Jüttler Sec. 5, Fig. 5b), one rational tensor-product Bézier surface per
//! segment: `u` the segment's local parameter, `v` the curve's. Library:
//! `motion::method::BuiltMotion::kinematic_surfaces` (`ExactMotion::kinematic_surfaces` under
//! `--scalar rational`), i.e. `motion::juttler::surface::RationalBezierSurface::kinematic`.
//!
//! The curve file is `{"points": [[x, y, z], ...], "weights": [w, ...]}` (weights optional,
//! default 1; at least one point; a weight may be zero: a control point at infinity, given by
//! its direction), the shape `gam trajectory` prints. Methods whose motions are not rational
//! exit 2, as for `gam trajectory`.

use crate::error::CliError;
use crate::interpolate::{build, usage};
use crate::precision::{self, MotionScalar, OutScalar, json_list};
use algebra_core::rational::Q;
use algebra_core::{MpFloat, Ring};
use motion::juttler::RationalBezier;
use motion::method::{BuildError, Method, SurfaceSegment};
use motion::schema::{Exact, SpecNumber};
use serde::Deserialize;
use serde_json::{Value, json};

/// The curve file, numbers in the format's number type.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, bound = "N: SpecNumber")]
struct CurveFile<N> {
    points: Vec<[N; 3]>,
    #[serde(default)]
    weights: Option<Vec<N>>,
}

/// The most control points of a curve.
const MAX_POINTS: usize = 1000;

/// The curve of the text `text` (named `path` in messages) in number type `N`, mapped by
/// `f`: homogeneous control points `(w, w p)`.
fn read_curve<N: SpecNumber, T: Ring>(
    path: &str,
    text: &str,
    f: &dyn Fn(&N) -> T,
) -> Result<RationalBezier<T>, CliError> {
    let text = crate::hermite::strip_comments(text);
    let c: CurveFile<N> = serde_json::from_str(&N::prepare_text(&text)).map_err(|e| {
        usage(path, format!("invalid curve: {e} (expected {{\"points\": [[x, y, z], ...], \"weights\": [w, ...]}})"))
    })?;
    let n = c.points.len();
    if !(1..=MAX_POINTS).contains(&n) {
        return Err(usage(path, format!("`points` must hold 1 to {MAX_POINTS} control points (got {n})")));
    }
    let weights: Vec<T> = match &c.weights {
        Some(w) if w.len() != n => return Err(usage(path, format!("`weights` has {} values for {n} points", w.len()))),
        Some(w) => w.iter().map(f).collect(),
        None => vec![T::one(); n],
    };
    if let Some(x) = c.points.iter().flatten().chain(c.weights.iter().flatten()).find(|x| !x.is_finite()) {
        return Err(usage(path, format!("the curve's numbers must be finite (got {})", x.to_f64())));
    }
    let control = c
        .points
        .iter()
        .zip(weights)
        .map(|(p, w)| {
            let [x, y, z] = p.each_ref().map(|c| f(c).mul_ref(&w));
            [w, x, y, z]
        })
        .collect();
    RationalBezier::new(control).map_err(|e| usage(path, e))
}

/// One surface: interval, degrees, weights (rows along `u`), affine control points.
type Patch<T> = (T, T, (usize, usize), Vec<Vec<T>>, Vec<Vec<[T; 3]>>);

/// The patches of the surfaces, each control point divided by its weight (a zero weight is a
/// point at infinity of the surface: exit 1, as `gam trajectory`).
fn patches<T: OutScalar>(
    method: Method,
    surfaces: Result<Vec<SurfaceSegment<T>>, BuildError>,
    label: &str,
) -> Result<Vec<Patch<T>>, CliError> {
    let surfaces = surfaces.map_err(|e| crate::trajectory::rational_error(method, label, e))?;
    let mut out = Vec::with_capacity(surfaces.len());
    for s in surfaces {
        let net = s.surface.control();
        let weights: Vec<Vec<T>> = net.iter().map(|row| row.iter().map(|h| h[0].clone()).collect()).collect();
        let mut points = Vec::with_capacity(net.len());
        for row in net {
            let mut r = Vec::with_capacity(row.len());
            for h in row {
                let inv = h[0].try_recip().ok_or_else(|| {
                    CliError::math(format!("{method}: a control point of the surface has weight zero (at infinity)"))
                })?;
                r.push([h[1].mul_ref(&inv), h[2].mul_ref(&inv), h[3].mul_ref(&inv)]);
            }
            points.push(r);
        }
        if !weights.iter().flatten().chain(points.iter().flatten().flatten()).all(crate::scalar::CliScalar::finite) {
            return Err(CliError::math(format!("{method}: the surface is not finite (overflow)")));
        }
        out.push((s.t0, s.t1, s.surface.degrees(), weights, points));
    }
    Ok(out)
}

/// The output, JSON or human.
fn render<T: OutScalar>(method: Method, patches: &[Patch<T>], json: bool) -> String {
    if json {
        let segs: Vec<Value> = patches
            .iter()
            .map(|(t0, t1, (du, dv), w, p)| {
                json!({"t0": t0.json(), "t1": t1.json(), "degrees": [du, dv],
                    "weights": w.iter().map(|r| json_list(r)).collect::<Vec<_>>(),
                    "points": p.iter().map(|r| r.iter().map(|q| json_list(q)).collect::<Vec<_>>()).collect::<Vec<_>>()})
            })
            .collect();
        return json!({ "segments": segs }).to_string();
    }
    let list = |v: &[T]| v.iter().map(OutScalar::text).collect::<Vec<_>>().join(", ");
    let mut lines = vec![format!(
        "{method}: kinematic surface as {} rational tensor-product Bézier patches (u: the segment's local parameter, v: the curve's)",
        patches.len()
    )];
    for (k, (t0, t1, (du, dv), w, p)) in patches.iter().enumerate() {
        lines.push(format!("segment {k} (t = {} .. {}): degrees ({du}, {dv})", t0.text(), t1.text()));
        for (i, (wr, pr)) in w.iter().zip(p).enumerate() {
            let cells: Vec<String> = wr
                .iter()
                .zip(pr)
                .enumerate()
                .map(|(j, (wj, pj))| format!("w{i}{j} = {}, P{i}{j} = [{}]", wj.text(), list(pj)))
                .collect();
            lines.push(format!("  {}", cells.join("; ")));
        }
    }
    lines.join("\n")
}

/// Runs `gam surface` on the spec file at `path` and the curve file at `curve`.
pub fn surface(path: &str, curve: &str, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    let (spec_text, curve_text) = (precision::read_file(path)?, precision::read_file(curve)?);
    surface_in((path, &spec_text), (curve, &curve_text), json, scalar)
}

/// `gam surface` of the spec and curve texts, each with the label that names it in messages.
pub(crate) fn surface_in(
    (path, spec_text): (&str, &str),
    (curve, curve_text): (&str, &str),
    json: bool,
    scalar: MotionScalar,
) -> Result<String, CliError> {
    match scalar {
        MotionScalar::F64 => {
            let x = read_curve::<f64, f64>(curve, curve_text, &|c| *c)?;
            let spec = crate::interpolate::read_text(path, spec_text)?
                .ok_or_else(|| usage(path, "invalid spec: missing field `method`"))?;
            let b = build(path, &spec)?;
            let method = b.motion.method();
            Ok(render(method, &patches(method, b.motion.kinematic_surfaces(&x), path)?, json))
        }
        MotionScalar::Rational => {
            let x = read_curve::<Exact, Q>(curve, curve_text, &|c| c.0.clone())?;
            let m = precision::build_exact(path, &precision::exact_spec(path, spec_text)?)?;
            Ok(render(m.method(), &patches(m.method(), m.kinematic_surfaces(&x), path)?, json))
        }
        MotionScalar::Mpfr(_) => scalar.run(|| {
            let x = read_curve::<Exact, MpFloat>(curve, curve_text, &|c| MpFloat::from_rational(&c.0))?;
            let b = precision::build_mpfr(path, &precision::exact_spec(path, spec_text)?)?;
            let method = b.method();
            Ok(render(method, &patches(method, b.kinematic_surfaces(&x), path)?, json))
        }),
    }
}
