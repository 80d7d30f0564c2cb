//! Named constructors (points, planes, lines, translators, rotors, motors), for algebras
//! recognised from their exact metric, never from their names:
//!
//! - **PGA**: a diagonal metric with one generator `g0` squaring to `0` and the others
//!   (`g1..gn`, `n = 2` or `3`) squaring to `+1`. The point `x` is the meet of the hyperplanes
//!   `x_k = const`: `(g1 - x1 g0) ∧ ... ∧ (gn - xn g0)`; a direction is its limit, a plane
//!   `n·x = d` is `n1 g1 + ... - d g0`; the line through two points their join `P ∨ Q`.
//!   The translator is `1 ± (1/2) Σ t_k g0 g_k` and the rotor `cos(θ/2) ± sin(θ/2) β(â)` with
//!   `β(a) = a1 g2 g3 + a2 g3 g1 + a3 g1 g2` (`g1 g2` in 2D); each sign is chosen here by acting
//!   with the candidate on points, exactly over `Q`, so that under [`apply`](crate::versor)
//!   (`x ↦ S x rev(S)`) the translator moves every point by `+t` and the rotor turns it by `+θ`
//!   about `a`, right-handed.
//! - **Euclidean** `G_2`, `G_3` (every generator squares to `+1`): the rotor, with the same rule
//!   acting on vectors.
//!
//! Each constructor is an expansion of products of *pieces* `(atoms, multivector)`: the
//! result's every coefficient is a sum of exact rational multiples of products of atoms
//! (parameter components, `cos(θ/2)`, `sin(θ/2)`, the unit axis). It returns the smallest
//! declared type holding its support, and is left out when no declared type holds it. The
//! emitter is [`crate::emit`]'s `named`.

use crate::spec::{CodegenError, ModuleSpec};
use algebra_core::Multivector;
use algebra_core::rational::Q;
use algebra_core::tables::Product;
use num_traits::{One, Zero};
use std::collections::BTreeMap;
use std::sync::Arc;

/// The names of every named constructor (the functions a module may get).
pub const NAMES: [&str; 14] = [
    "up",
    "down",
    "sphere",
    "dilator",
    "point",
    "direction",
    "plane",
    "line",
    "line_through",
    "translator",
    "rotor",
    "motor",
    "rotor_about_line",
    "rotor_about_point",
];

/// Whether `name` is one of the named constructors ([`NAMES`]).
pub fn is_named(name: &str) -> bool {
    NAMES.contains(&name)
}

/// A factor of a term.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Atom {
    /// Component `k` of array parameter `p`.
    Param(usize, usize),
    /// `cos(θ/2)` of the angle parameter.
    Cos,
    /// `sin(θ/2)` of the angle parameter.
    Sin,
    /// Component `k` of the unit axis (`axis / |axis|`).
    Unit(usize),
    /// `cosh(ln(scale)/2) = (√scale + 1/√scale)/2` of the scale parameter.
    Cosh,
    /// `sinh(ln(scale)/2) = (√scale - 1/√scale)/2`.
    Sinh,
}

/// A parameter of a constructor.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Param {
    /// `name: &[T; n]`.
    Array(&'static str, usize),
    /// The axis `&[T; n]` (normalised; a zero or non-finite axis is an error).
    Axis(usize),
    /// The angle `&T` (radians).
    Angle,
    /// The scale factor `&T` (positive).
    Scale,
}

/// One term of an output field: `coef · Π atoms`.
pub type Monomial = (Vec<Atom>, Q);

/// One named constructor.
#[derive(Debug, Clone)]
pub struct Constructor {
    /// The function's name.
    pub name: &'static str,
    /// Its parameters, in order.
    pub params: Vec<Param>,
    /// The output type.
    pub out: usize,
    /// Per field of the output type: its terms (canonical coefficients; the emitter folds the
    /// fields' orientation signs in).
    pub fields: Vec<Vec<Monomial>>,
    /// What it builds, for the docs.
    pub doc: String,
}

/// The recognised geometry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Geometry {
    /// Projective: the null generator and the Euclidean ones.
    Pga {
        /// `g0`.
        null: usize,
        /// `g1..gn`.
        euclid: Vec<usize>,
    },
    /// Euclidean `G_n`.
    Euclid(Vec<usize>),
    /// Conformal: the Euclidean generators and the null vectors `o` (origin) and `∞`
    /// (infinity), `o · ∞ = -1`, as generator combinations.
    Cga {
        /// `g1..gn`.
        euclid: Vec<usize>,
        /// `o = Σ c_i g_i`.
        origin: Vec<(usize, Q)>,
        /// `∞ = Σ c_i g_i`.
        infinity: Vec<(usize, Q)>,
    },
}

/// The geometry of `spec`'s metric, if recognised.
pub fn recognise(spec: &ModuleSpec) -> Option<Geometry> {
    let m = spec.algebra.metric();
    let dim = m.dimension();
    let g = |i: usize, j: usize| m.gram(i, j).cloned().unwrap_or_else(|_| Q::zero());
    let sq: Vec<Q> = (0..dim).map(|i| g(i, i)).collect();
    if !m.is_diagonal() {
        // a null pair a < b (a² = b² = 0, a·b = c ≠ 0), everything else orthonormal and positive
        let off: Vec<(usize, usize)> =
            (0..dim).flat_map(|i| (i + 1..dim).map(move |j| (i, j))).filter(|&(i, j)| !g(i, j).is_zero()).collect();
        let [(a, b)] = off.as_slice() else { return None };
        let euclid: Vec<usize> = (0..dim).filter(|i| i != a && i != b).collect();
        if !sq[*a].is_zero()
            || !sq[*b].is_zero()
            || euclid.iter().any(|&i| sq[i] != Q::one())
            || !(2..=3).contains(&euclid.len())
        {
            return None;
        }
        let c = g(*a, *b);
        return Some(Geometry::Cga { euclid, origin: vec![(*a, -Q::one() / c)], infinity: vec![(*b, Q::one())] });
    }
    let minus: Vec<usize> = (0..dim).filter(|&i| sq[i] == -Q::one()).collect();
    if let [e_minus] = minus.as_slice() {
        let pos: Vec<usize> = (0..dim).filter(|&i| sq[i] == Q::one()).collect();
        if pos.len() + 1 != dim || !(3..=4).contains(&pos.len()) {
            return None;
        }
        // e+ is the last positive generator (the tables cannot tell which one the user meant)
        let e_plus = *pos.last().expect("3 or 4 positive generators");
        let half = Q::new(1.into(), 2.into());
        return Some(Geometry::Cga {
            euclid: pos[..pos.len() - 1].to_vec(),
            origin: vec![(*e_minus, half.clone()), (e_plus, -half)],
            infinity: vec![(*e_minus, Q::one()), (e_plus, Q::one())],
        });
    }
    let null: Vec<usize> = (0..sq.len()).filter(|&i| sq[i].is_zero()).collect();
    let pos: Vec<usize> = (0..sq.len()).filter(|&i| sq[i] == Q::one()).collect();
    if null.len() + pos.len() != sq.len() || !(2..=3).contains(&pos.len()) {
        return None;
    }
    match null.as_slice() {
        [] => Some(Geometry::Euclid(pos)),
        [g0] => Some(Geometry::Pga { null: *g0, euclid: pos }),
        _ => None,
    }
}

/// A sum of `(atoms, multivector)` pieces.
type Pieces = Vec<(Vec<Atom>, Multivector<Q>)>;

/// The point of a geometry at Euclidean coordinates.
type PointAt<'a> = dyn Fn(&[Q]) -> Multivector<Q> + 'a;

struct Ctx {
    alg: Arc<algebra_core::Algebra>,
    basis: algebra_core::Basis,
}

impl Ctx {
    fn generator(&self, i: usize) -> Multivector<Q> {
        Multivector::from_mask(&self.alg, self.basis, 1 << i).expect("a generator")
    }

    fn combo(&self, c: &[(usize, Q)]) -> Multivector<Q> {
        c.iter()
            .fold(self.scalar(Q::zero()), |acc, (i, q)| acc.try_add(&self.generator(*i).scale(q)).expect("one algebra"))
    }

    fn scalar(&self, q: Q) -> Multivector<Q> {
        Multivector::scalar(&self.alg, self.basis, q)
    }

    fn product(&self, a: &Pieces, b: &Pieces, p: Product) -> Pieces {
        let mut out = Vec::new();
        for (x, u) in a {
            for (y, v) in b {
                let mut atoms = [x.as_slice(), y.as_slice()].concat();
                atoms.sort();
                out.push((atoms, u.product(v, p)));
            }
        }
        out
    }

    /// `(g_k - x_k g0)` over the Euclidean generators, outer-multiplied: the point `x`
    /// (parameter `param`), or only its linear part (a direction) when `direction`.
    fn point(&self, null: usize, euclid: &[usize], param: usize, direction: bool) -> Pieces {
        let mut acc: Pieces = vec![(vec![], self.scalar(Q::one()))];
        for (k, &g) in euclid.iter().enumerate() {
            let factor = vec![
                (vec![], self.generator(g)),
                (vec![Atom::Param(param, k)], self.generator(null).scale(&-Q::one())),
            ];
            acc = self.product(&acc, &factor, Product::Outer);
        }
        if direction {
            acc.retain(|(atoms, _)| !atoms.is_empty());
        }
        acc
    }

    /// `1 + sign/2 Σ t_k n g_k` for the null vector `n` (`g0` in PGA, `∞` in CGA).
    fn translator(&self, null: &Multivector<Q>, euclid: &[usize], param: usize, sign: &Q) -> Pieces {
        let half = sign * Q::new(1.into(), 2.into());
        let mut out: Pieces = vec![(vec![], self.scalar(Q::one()))];
        for (k, &g) in euclid.iter().enumerate() {
            out.push((vec![Atom::Param(param, k)], null.gp(&self.generator(g)).scale(&half)));
        }
        out
    }

    /// `β(â)`: the bivector of the rotation about the unit axis `â` (3D, its atoms
    /// [`Atom::Unit`]) or in the plane (2D).
    fn beta(&self, euclid: &[usize]) -> Pieces {
        let g = |k: usize| self.generator(euclid[k]);
        match euclid.len() {
            3 => (0..3).map(|k| (vec![Atom::Unit(k)], g((k + 1) % 3).gp(&g((k + 2) % 3)))).collect(),
            _ => vec![(vec![], g(0).gp(&g(1)))],
        }
    }

    /// `cos(θ/2) + sign sin(θ/2) β(â)`.
    fn rotor(&self, euclid: &[usize], sign: &Q) -> Pieces {
        let mut out: Pieces = vec![(vec![Atom::Cos], self.scalar(Q::one()))];
        for (mut atoms, b) in self.beta(euclid) {
            atoms.push(Atom::Sin);
            atoms.sort();
            out.push((atoms, b.scale(sign)));
        }
        out
    }

    /// Adds `translator`, `rotor`, `motor` and the rotation about a line (3D) or point (2D),
    /// for the null vector `null` of the translations; `point(x)` is the point at `x`. The
    /// translator's and rotor's signs are the ones for which `apply` moves the origin to `e1`
    /// and turns `e1` into `e2` by a quarter turn about the last axis (the plane `g1 g2` in 2D).
    fn rigid_motions(
        &self,
        euclid: &[usize],
        (null, point): (&Multivector<Q>, &PointAt),
        translator_doc: &str,
        add: &mut dyn FnMut(&'static str, Vec<Param>, Pieces, String),
    ) -> Result<(), CodegenError> {
        let n = euclid.len();
        let unit = |k: usize| -> Vec<Q> { (0..n).map(|i| if i == k { Q::one() } else { Q::zero() }).collect() };
        let (origin, e1, e2) = (point(&vec![Q::zero(); n]), point(&unit(0)), point(&unit(1)));
        let t_sign = sign_where("translator", |s| {
            let t = self.eval(&self.translator(null, euclid, 0, s), |a| {
                if a == Atom::Param(0, 0) { Q::one() } else { Q::zero() }
            });
            apply(&t, &origin) == e1
        })?;
        let r_sign = sign_where("rotor", |s| {
            // unnormalised (1 + sign β): the quarter turn, times |1 + β|² = 2
            let r = self.eval(&self.rotor(euclid, s), |a| {
                if a == Atom::Unit(n - 1) || a == Atom::Cos || a == Atom::Sin { Q::one() } else { Q::zero() }
            });
            apply(&r, &e1).try_sub(&e2.scale(&Q::from_integer(2.into()))).is_ok_and(|d| d.is_zero())
        })?;
        let (t_sign, r_sign) = (&t_sign, &r_sign);
        let n = euclid.len();
        let translator = self.translator(null, euclid, 0, t_sign);
        add("translator", vec![Param::Array("t", n)], translator.clone(), translator_doc.into());
        let rotor = self.rotor(euclid, r_sign);
        let (rotor_params, motor_params) = if n == 3 {
            (vec![Param::Axis(3), Param::Angle], vec![Param::Axis(3), Param::Angle, Param::Array("t", 3)])
        } else {
            (vec![Param::Angle], vec![Param::Angle, Param::Array("t", 2)])
        };
        add("rotor", rotor_params, rotor.clone(), rotor_doc(n, "point"));
        // the motor's translation is its only array parameter (index 0), after axis and angle
        add(
            "motor",
            motor_params,
            self.product(&translator, &rotor, Product::Geometric),
            "The rigid motion `x ↦ R x + t` (rotate by `angle` about the axis through the origin, then translate by `t`): `translator(t) rotor(..)`; `apply` (`x ↦ S x rev(S)`) moves points by it.".into(),
        );
        // about the line (point) through p: translator(p) rotor translator(-p)
        let back: Pieces = translator
            .iter()
            .map(|(atoms, mv)| (atoms.clone(), if atoms.is_empty() { mv.clone() } else { mv.scale(&-Q::one()) }))
            .collect();
        let about = self.product(&self.product(&translator, &rotor, Product::Geometric), &back, Product::Geometric);
        let (name, params, what) = if n == 3 {
            ("rotor_about_line", vec![Param::Array("p", 3), Param::Axis(3), Param::Angle], "axis `axis`")
        } else {
            ("rotor_about_point", vec![Param::Array("p", 2), Param::Angle], "point")
        };
        let doc =
            format!("The rotation by `angle` about the {what} through `p`: `translator(p) rotor(..) translator(-p)`.");
        add(name, params, about, doc);
        Ok(())
    }

    /// The multivector of `pieces` with every atom set to the value `at` gives it.
    fn eval(&self, pieces: &Pieces, at: impl Fn(Atom) -> Q) -> Multivector<Q> {
        let mut acc = self.scalar(Q::zero());
        for (atoms, mv) in pieces {
            let c = atoms.iter().fold(Q::one(), |c, a| c * at(*a));
            acc = acc.try_add(&mv.scale(&c)).expect("one algebra");
        }
        acc
    }
}

/// `S x rev(S)`: [`Multivector::sandwich`] (`rev(S) x S`) of `rev(S)`.
fn apply(s: &Multivector<Q>, x: &Multivector<Q>) -> Multivector<Q> {
    s.reverse().sandwich(x)
}

/// `a = k b` for some rational `k > 0`.
fn positive_multiple(a: &Multivector<Q>, b: &Multivector<Q>) -> bool {
    let (ca, cb) = (a.coeffs(), b.coeffs());
    let Some(i) = cb.iter().position(|c| !c.is_zero()) else { return false };
    let k = &ca[i] / &cb[i];
    k > Q::zero() && ca.iter().zip(cb).all(|(x, y)| *x == &k * y)
}

/// The sign in `{+1, -1}` for which `check(sign)` holds.
fn sign_where(what: &str, check: impl Fn(&Q) -> bool) -> Result<Q, CodegenError> {
    [Q::one(), -Q::one()]
        .into_iter()
        .find(|s| check(s))
        .ok_or_else(|| CodegenError::NamedConstructor(format!("no sign makes the {what} act as expected")))
}

/// Collects `pieces` into per-field terms of the smallest declared type holding them.
fn collect(spec: &ModuleSpec, pieces: &Pieces) -> Option<(usize, Vec<Vec<Monomial>>)> {
    let mut by_mask: BTreeMap<u32, BTreeMap<Vec<Atom>, Q>> = BTreeMap::new();
    for (atoms, mv) in pieces {
        for (mask, c) in mv.coeffs().iter().enumerate() {
            if !c.is_zero() {
                *by_mask.entry(mask as u32).or_default().entry(atoms.clone()).or_insert_with(Q::zero) += c;
            }
        }
    }
    by_mask.retain(|_, terms| {
        terms.retain(|_, c| !c.is_zero());
        !terms.is_empty()
    });
    let masks: Vec<u32> = by_mask.keys().copied().collect();
    let declared = (0..spec.types.len()).filter(|&t| masks.iter().all(|m| spec.types[t].elements.contains(m)));
    let out = declared.min_by_key(|&t| spec.types[t].elements.len())?;
    let fields = spec.types[out]
        .elements
        .iter()
        .map(|m| by_mask.get(m).map(|t| t.iter().map(|(a, c)| (a.clone(), c.clone())).collect()).unwrap_or_default())
        .collect();
    Some((out, fields))
}

/// The named constructors of `spec` (its first `declared` types are the user's): empty when
/// the algebra is not recognised.
pub fn constructors(spec: &ModuleSpec, declared: usize) -> Result<Vec<Constructor>, CodegenError> {
    let Some(geometry) = recognise(spec) else { return Ok(vec![]) };
    let ctx = Ctx { alg: spec.algebra.clone(), basis: spec.basis };
    let view = ModuleSpec { types: spec.types[..declared].to_vec(), ..spec.clone() };
    let mut out = Vec::new();
    let mut add = |name: &'static str, params: Vec<Param>, pieces: Pieces, doc: String| {
        if let Some((ty, fields)) = collect(&view, &pieces) {
            out.push(Constructor { name, params, out: ty, fields, doc });
        }
    };
    match geometry {
        Geometry::Euclid(euclid) => {
            let n = euclid.len();
            let sign = sign_where("rotor", |s| {
                // a quarter turn (unnormalised: 1 + sign β) takes g1 to a positive multiple of g2
                let r = ctx.eval(&ctx.rotor(&euclid, s), |a| {
                    if a == Atom::Unit(2) || a == Atom::Cos || a == Atom::Sin { Q::one() } else { Q::zero() }
                });
                positive_multiple(&apply(&r, &ctx.generator(euclid[0])), &ctx.generator(euclid[1]))
            })?;
            let params = if n == 3 { vec![Param::Axis(3), Param::Angle] } else { vec![Param::Angle] };
            let doc = rotor_doc(n, "vector");
            add("rotor", params, ctx.rotor(&euclid, &sign), doc);
        }
        Geometry::Pga { null, euclid } => {
            let n = euclid.len();
            let point = ctx.point(null, &euclid, 0, false);
            add(
                "point",
                vec![Param::Array("p", n)],
                point.clone(),
                format!(
                    "The point `p`: the meet of the {} `x_k = p_k`, weight `+1` on the Euclidean pseudoscalar.",
                    if n == 3 { "planes" } else { "lines" }
                ),
            );
            add(
                "direction",
                vec![Param::Array("d", n)],
                ctx.point(null, &euclid, 0, true),
                "The direction `d` (the ideal point, weight 0): the point `t d` divided by `t` as `t` grows.".into(),
            );
            let mut hyper: Pieces =
                (0..n).map(|k| (vec![Atom::Param(0, k)], ctx.generator(euclid[k]))).collect::<Vec<_>>();
            hyper.push((vec![Atom::Param(1, 0)], ctx.generator(null).scale(&-Q::one())));
            let (name, what) = if n == 3 { ("plane", "plane") } else { ("line", "line") };
            add(
                name,
                vec![Param::Array("normal", n), Param::Array("distance", 1)],
                hyper,
                format!(
                    "The {what} `normal · x = distance` (`normal` need not be a unit vector): `Σ normal_k g_k - distance g0`."
                ),
            );
            let q = ctx.point(null, &euclid, 1, false);
            let join = ctx.product(&point, &q, Product::Regressive);
            add(
                "line_through",
                vec![Param::Array("p", n), Param::Array("q", n)],
                join,
                "The line through the points `p` and `q`: their join `point(p) ∨ point(q)` (the regressive product)."
                    .into(),
            );
            let at = |x: &[Q]| ctx.eval(&point, |a| if let Atom::Param(0, k) = a { x[k].clone() } else { Q::zero() });
            let doc = "The translation by `t`: `apply` (`x ↦ S x rev(S)`) moves every point by `+t`.";
            ctx.rigid_motions(&euclid, (&ctx.generator(null), &at), doc, &mut add)?;
        }
        Geometry::Cga { euclid, origin, infinity } => {
            let n = euclid.len();
            let (o, inf) = (ctx.combo(&origin), ctx.combo(&infinity));
            let half = Q::new(1.into(), 2.into());
            let up = |param: usize| -> Pieces {
                let mut out: Pieces = vec![(vec![], o.clone())];
                for (k, &g) in euclid.iter().enumerate() {
                    out.push((vec![Atom::Param(param, k)], ctx.generator(g)));
                    out.push((vec![Atom::Param(param, k), Atom::Param(param, k)], inf.scale(&half)));
                }
                out
            };
            let at = |x: &[Q]| ctx.eval(&up(0), |a| if let Atom::Param(0, k) = a { x[k].clone() } else { Q::zero() });
            let unit = |k: usize| -> Vec<Q> { (0..n).map(|i| if i == k { Q::one() } else { Q::zero() }).collect() };
            let e = o.op(&inf);
            let dilator = |sign: &Q| -> Pieces {
                vec![(vec![Atom::Cosh], ctx.scalar(Q::one())), (vec![Atom::Sinh], e.scale(sign))]
            };
            let d_sign = sign_where("dilator", |s| {
                // scale 4: cosh(ln 2) = 5/4, sinh(ln 2) = 3/4; e1 goes to a multiple of up(4 e1)
                let d = ctx.eval(&dilator(s), |a| match a {
                    Atom::Cosh => Q::new(5.into(), 4.into()),
                    Atom::Sinh => Q::new(3.into(), 4.into()),
                    _ => Q::zero(),
                });
                let mut four = unit(0);
                four[0] = Q::from_integer(4.into());
                positive_multiple(&apply(&d, &at(&unit(0))), &at(&four))
            })?;
            let up_doc = "The conformal point of `p`: `up(p) = o + p + (1/2) p² ∞` (`o` the origin, `∞` infinity, `o · ∞ = -1`; `up(p) · up(q) = -|p - q|²/2`).";
            add("up", vec![Param::Array("p", n)], up(0), up_doc.into());
            add("point", vec![Param::Array("p", n)], up(0), format!("{up_doc} The same as `up`."));
            let mut sphere = up(0);
            sphere.push((vec![Atom::Param(1, 0), Atom::Param(1, 0)], inf.scale(&-half.clone())));
            add(
                "sphere",
                vec![Param::Array("center", n), Param::Array("radius", 1)],
                sphere,
                format!(
                    "The dual {} of `center` and `radius`: `up(center) - (1/2) radius² ∞`; `up(x) · sphere = 0` exactly on it.",
                    if n == 3 { "sphere" } else { "circle" }
                ),
            );
            let mut hyper: Pieces = (0..n).map(|k| (vec![Atom::Param(0, k)], ctx.generator(euclid[k]))).collect();
            hyper.push((vec![Atom::Param(1, 0)], inf.clone()));
            let name = if n == 3 { "plane" } else { "line" };
            add(
                name,
                vec![Param::Array("normal", n), Param::Array("distance", 1)],
                hyper,
                format!(
                    "The dual {name} `normal · x = distance`: `normal + distance ∞`; `up(x) · {name}` is `normal · x - distance`."
                ),
            );
            add(
                "dilator",
                vec![Param::Scale],
                dilator(&d_sign),
                "The scaling by `scale > 0` about the origin: `cosh(ln(scale)/2) ± sinh(ln(scale)/2) o∧∞`, the sign chosen so that `apply` takes `up(p)` to a positive multiple of `up(scale p)` (normalise with `down`). An error for a scale that is not positive and finite.".into(),
            );
            let doc = "The translation by `t`: `1 ± (1/2) t ∞`, the sign chosen so that `apply` (`x ↦ S x rev(S)`) moves `up(p)` to `up(p + t)`.";
            ctx.rigid_motions(&euclid, (&inf, &at), doc, &mut add)?;
        }
    }
    Ok(out)
}

/// `down`: the Euclidean point of a conformal point, `x_k = (X · g_k) / (-X · ∞)`.
#[derive(Debug, Clone)]
pub struct Down {
    /// The input type (the type of `up`).
    pub input: usize,
    /// Per field of the input: its coefficient in `-X · ∞` (canonical).
    pub weight: Vec<Q>,
    /// Per Euclidean coordinate, per field of the input: its coefficient in `X · g_k`.
    pub coords: Vec<Vec<Q>>,
}

/// The `down` of a conformal module, given its [`constructors`] (`None` without an `up`,
/// which is the case for every other module).
pub fn down(spec: &ModuleSpec, constructors: &[Constructor]) -> Option<Down> {
    let input = constructors.iter().find(|c| c.name == "up")?.out;
    let Some(Geometry::Cga { euclid, infinity, .. }) = recognise(spec) else { return None };
    let ctx = Ctx { alg: spec.algebra.clone(), basis: spec.basis };
    let inf = ctx.combo(&infinity);
    let fields: Vec<Multivector<Q>> = spec.types[input]
        .elements
        .iter()
        .map(|m| Multivector::from_mask(&ctx.alg, ctx.basis, *m).expect("a mask"))
        .collect();
    let weight = fields.iter().map(|f| -f.sp(&inf).scalar_part()).collect();
    let coords =
        euclid.iter().map(|&g| fields.iter().map(|f| f.sp(&ctx.generator(g)).scalar_part()).collect()).collect();
    Some(Down { input, weight, coords })
}

fn rotor_doc(n: usize, acted: &str) -> String {
    if n == 3 {
        format!(
            "The rotation by `angle` (radians) about `axis` through the origin, right-handed: `cos(angle/2) ± sin(angle/2) β(axis/|axis|)`, the sign chosen from the product tables so that `apply` (`x ↦ S x rev(S)`) turns every {acted} by `+angle` (a quarter turn about `e3` takes `e1` to `e2`). `sandwich` (`rev(S) x S`) turns the other way. An error for a zero or non-finite axis or angle."
        )
    } else {
        format!(
            "The rotation by `angle` (radians) in the plane, counter-clockwise: `apply` (`x ↦ S x rev(S)`) turns every {acted} by `+angle` (a quarter turn takes `e1` to `e2`). An error for a non-finite angle."
        )
    }
}

#[cfg(test)]
mod tests {
    use super::{NAMES, constructors};
    use crate::ModuleSpec;
    use algebra_core::{Algebra, Basis, Metric};

    /// `--standalone` drops the named constructors by [`NAMES`]: every function any
    /// recognised geometry emits must be listed there.
    #[test]
    fn every_constructor_is_named() {
        let builtin = |n: &str| Algebra::builtin(n).unwrap();
        let pga2 = Algebra::new("pga2", Metric::diagonal(2, 0, 1).unwrap());
        let cases = [
            (builtin("g3"), Basis::Blade),
            (builtin("pga3"), Basis::Blade),
            (pga2, Basis::Blade),
            (builtin("cga"), Basis::Blade),
            (builtin("cga-null"), Basis::Product),
        ];
        for (a, basis) in cases {
            let types = ModuleSpec::parse_types("V=grade1;B=grade2;M=even;A=all", &a).unwrap();
            let spec = ModuleSpec::new(a.name(), a.metric().clone(), basis, types).unwrap();
            let all = constructors(&spec, spec.types.len()).unwrap();
            assert!(!all.is_empty(), "{}", a.name());
            for c in &all {
                assert!(NAMES.contains(&c.name), "{}: `{}` is not in NAMES", a.name(), c.name);
            }
        }
        assert!(NAMES.contains(&"down"));
    }
}
