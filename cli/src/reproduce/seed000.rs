//! Seed 000: Fig. 4 captions, Fig. 5(a) and 5(b) (compatible pairs, κ, δ,
//! hodographs, convolution and its cusp), Fig. 9/10 (Prop 6.1's critical points).

use super::printed::{constant_of, parse_expr, PrintedValue, Val};
use super::{data, Claim, ClaimGroup, Verdict};
use lncert::curve::{Bezier, V2};
use lncert::ln::circle::ArcApprox;
use lncert::ln::cubic::{deltas_from_rho, tau_from_rho, LnFrame, Tau};
use lncert::ln::direct::singular_points;
use lncert::ln::pair::{
    convolution_has_interior_cusp, cusp_parameter, prop_4_4_as_printed, CompatiblePair,
    Convolution, KappaChoice, LnPair,
};
use lncert::poly::{Poly, Span};
use lncert::scalar::{
    parse_rational, sin_cos_enclosure, Interval, IntervalExt, Rational, Scalar, ScalarSqrt, Sign,
    Surd,
};
use serde_json::Value;

type R<T> = Result<T, String>;

fn q(v: &Value) -> R<Rational> {
    super::json_rational(v)
}
fn pt(v: &Value) -> R<V2<Surd>> {
    Ok(V2::new(
        Surd::rational(q(&v[0])?),
        Surd::rational(q(&v[1])?),
    ))
}
fn frame(v: &Value) -> R<LnFrame<Surd>> {
    LnFrame::new(pt(&v["b0"])?, pt(&v["bm"])?, pt(&v["b3"])?).map_err(|e| e.to_string())
}

/// `value (≈ decimal)` for details.
pub(crate) fn show(x: &Surd) -> String {
    match x.enclosure() {
        Some(i) => format!("{x} (≈ {:.6})", i.mid()),
        None => x.to_string(),
    }
}

fn equal(a: &Surd, b: &Surd) -> Option<bool> {
    a.exact_eq(b)
}

/// Compares a printed value with the engine's exact value: every closed form
/// must be equal, every decimal must round the exact value.
pub(crate) fn judge(printed: &str, exact: &Surd) -> (Verdict, String) {
    let p = PrintedValue::parse(printed);
    let mut wrong = Vec::new();
    let mut undecided = false;
    for (text, v) in &p.exact {
        let val = match v {
            Val::Scalar(poly) => constant_of(poly),
            _ => None,
        };
        match val.as_ref().and_then(|c| equal(c, exact)) {
            Some(true) => {}
            Some(false) => wrong.push(format!("printed {text} = {}", show(val.as_ref().unwrap()))),
            None => undecided = true,
        }
    }
    let mut decimals_ok = Vec::new();
    for d in &p.decimals {
        let ok = Interval::printed(d)
            .zip(exact.enclosure())
            .map(|(pi, e)| e.subset(pi));
        match ok {
            Some(true) => decimals_ok.push(d.clone()),
            Some(false) => wrong.push(format!("printed decimal {d} does not round the true value")),
            None => undecided = true,
        }
    }
    let truth = format!("engine: {}", show(exact));
    if !wrong.is_empty() {
        let agree = if decimals_ok.is_empty() {
            String::new()
        } else {
            format!(
                " (the printed decimal {} agrees with the engine: the closed form is the misprint)",
                decimals_ok.join(", ")
            )
        };
        (
            Verdict::Erratum,
            format!("{truth}; {}{agree}", wrong.join("; ")),
        )
    } else if undecided || (p.exact.is_empty() && p.decimals.is_empty()) {
        (Verdict::Undecided, truth)
    } else {
        (Verdict::Certified, truth)
    }
}

/// Exact equality of a printed vector polynomial with a computed one.
fn judge_vector(printed: &str, x: &Poly<Surd>, y: &Poly<Surd>) -> (Verdict, String) {
    let fmt = |p: &Poly<Surd>| {
        p.coeffs()
            .iter()
            .map(|c| c.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let engine = format!(
        "engine: x' coefficients [{}], y' coefficients [{}] (power basis)",
        fmt(x),
        fmt(y)
    );
    match parse_expr(printed) {
        Ok(Val::Vector(px, py)) => {
            let zero = |p: Poly<Surd>| {
                p.coeffs()
                    .iter()
                    .map(|c| c.sign().is_zero())
                    .try_fold(true, |a, b| Some(a && b?))
            };
            match (zero(px.sub(x)), zero(py.sub(y))) {
                (Some(true), Some(true)) => (
                    Verdict::Certified,
                    format!("equal as polynomials; {engine}"),
                ),
                (Some(_), Some(_)) => (
                    Verdict::Erratum,
                    format!("printed [{}], [{}] differ; {engine}", fmt(&px), fmt(&py)),
                ),
                _ => (Verdict::Undecided, engine),
            }
        }
        _ => (
            Verdict::Undecided,
            format!("could not read the printed expression; {engine}"),
        ),
    }
}

fn unit_normal(d: &V2<Surd>) -> Option<V2<Surd>> {
    let len = d.norm2().sqrt()?;
    let r = d.rot90();
    Some(V2::new(r.x.div(&len)?, r.y.div(&len)?))
}

fn printed_vector(v: &Value) -> Option<V2<Surd>> {
    let get = |x: &Value| PrintedValue::parse(x.as_str()?).constant();
    Some(V2::new(get(&v[0])?, get(&v[1])?))
}

/// Checks a printed unit normal against both ends of the left frame.
fn judge_normal(which: usize, printed: &Value, f: &LnFrame<Surd>) -> (Verdict, String) {
    let (Some(n), Some(n0), Some(n1)) = (
        printed_vector(printed),
        unit_normal(&f.d0()),
        unit_normal(&f.d1()),
    ) else {
        return (Verdict::Undecided, "could not evaluate".into());
    };
    let eq = |a: &V2<Surd>, b: &V2<Surd>| Some(equal(&a.x, &b.x)? && equal(&a.y, &b.y)?);
    let same = |a: &V2<Surd>, b: &V2<Surd>| Some(eq(a, b)? || eq(a, &b.neg())?);
    let expect = if which == 0 { &n0 } else { &n1 };
    let other = if which == 0 { &n1 } else { &n0 };
    let txt = |v: &V2<Surd>| format!("({}, {})", v.x, v.y);
    let detail = format!(
        "R∇b{which}/|∇b{which}| = {} (R = rotation by +π/2); printed {}",
        txt(expect),
        txt(&n)
    );
    match (same(&n, expect), same(&n, other)) {
        (Some(true), _) => {
            let orient = if eq(&n, expect) == Some(true) { "same orientation as R∇b" } else { "opposite orientation to R∇b" };
            (Verdict::Certified, format!("{detail}: a unit normal at that end ({orient})"))
        }
        (Some(false), Some(true)) => (
            Verdict::Erratum,
            format!("{detail}: the printed vector is the unit normal at the OTHER end — N0 and N1 are swapped"),
        ),
        (Some(false), Some(false)) => (Verdict::Erratum, format!("{detail}: not a unit normal at either end")),
        _ => (Verdict::Undecided, detail),
    }
}

/// One case of Fig. 5: its data, the printed text values, the source label.
struct Fig5<'a> {
    case: &'a str,
    d: &'a Value,
    text: &'a Value,
    src: String,
}

impl Fig5<'_> {
    /// The claim id `000-fig5{case}-{s}`.
    fn id(&self, s: &str) -> String {
        format!("000-fig5{}-{s}", self.case)
    }
}

/// The hodograph of `c` in the power basis.
fn hodo(c: &Bezier<Surd>) -> (Poly<Surd>, Poly<Surd>) {
    let (x, y) = c.hodograph().power_coords();
    (x, y)
}

fn fig5(out: &mut Vec<Claim>, case: &str) -> R<()> {
    let all: Value = serde_json::from_str(data::FIG5).map_err(|e| e.to_string())?;
    let text: Value = serde_json::from_str(data::TEXT).map_err(|e| e.to_string())?;
    let f = Fig5 {
        case,
        d: &all[case],
        text: &text,
        src: format!("seed 000 Fig. 5({case})"),
    };
    let (l, r) = (frame(&f.d["left"])?, frame(&f.d["right"])?);
    let pair = CompatiblePair::new(l.clone(), r.clone()).map_err(|e| e.to_string())?;
    let lam_l = fig5_pair(out, &f, &pair, &l, &r)?;
    fig5_kappa_interval(out, &f, &pair, &lam_l)?;
    // δ's from κ = geometric mean (exact in Q(√q)).
    let ln = pair
        .ln_pair(&KappaChoice::GeometricMean)
        .map_err(|e| e.to_string())?;
    fig5_deltas(out, &f, &ln);
    fig5_hodographs(out, &f, &ln);
    // Convolution.
    let conv = pair.convolution(&ln).map_err(|e| e.to_string())?;
    let (cx, cy) = hodo(&conv.curve);
    fig5_convolution(out, &f, &conv, &cx, &cy);
    fig5_cusp(out, &f, &conv, &cx, &cy);
    Ok(())
}

/// The pair: compatible, its normals N0 and N1, λl, λr and κ; returns λl.
fn fig5_pair(
    out: &mut Vec<Claim>,
    f: &Fig5,
    pair: &CompatiblePair<Surd>,
    l: &LnFrame<Surd>,
    r: &LnFrame<Surd>,
) -> R<Surd> {
    let (d, src) = (f.d, &f.src);
    let id = |s: &str| f.id(s);
    let qr = pair.ratio();
    let orient = if pair.c0.sign() == Sign::Positive {
        "parallel"
    } else {
        "anti-parallel"
    };
    let ok = pair.remark_4_3() == Some(true) && pair.prop_4_2() == Some(true);
    out.push(Claim::new(
        &id("compatible"),
        src,
        "the two curves are compatible and λl, λr satisfy eq. (7)",
        if ok {
            Verdict::Certified
        } else {
            Verdict::Refuted
        },
        format!(
            "end tangents {orient} (c0 = {}, c1 = {}); λr/λl = {} exactly",
            pair.c0, pair.c1, qr
        ),
    ));
    for (which, key) in [(0, "N0_printed"), (1, "N1_printed")] {
        let (v, det) = judge_normal(which, &d[key], l);
        out.push(Claim::new(
            &id(&format!("N{which}")),
            src,
            format!("N{which} = {}", d[key]),
            v,
            det,
        ));
    }
    let lam_l = l.lambda().ok_or("λl")?;
    let lam_r = r.lambda().ok_or("λr")?;
    for (key, lam) in [("lambda_l_printed", &lam_l), ("lambda_r_printed", &lam_r)] {
        let p = d[key].as_str().unwrap_or_default();
        let (v, det) = judge(p, lam);
        out.push(Claim::new(
            &id(key.trim_end_matches("_printed")),
            src,
            format!("{} = {p}", &key[..8]),
            v,
            det,
        ));
    }
    // κ = sqrt(λl λr) = sqrt(λl² q), exact.
    let kappa2 = (l.lambda2().ok_or("λ²")? * qr.clone())
        .as_rational()
        .ok_or("κ²")?;
    let kappa = Surd::sqrt_of(&kappa2).ok_or("κ")?;
    let p = d["kappa_printed"].as_str().unwrap_or_default();
    let (v, det) = judge(p, &kappa);
    out.push(Claim::new(&id("kappa"), src, format!("κ = {p}"), v, det));
    Ok(lam_l)
}

/// The admissible κ interval λl·((1/2, 2) ∩ (q/2, 2q)) against the printed one.
fn fig5_kappa_interval(
    out: &mut Vec<Claim>,
    f: &Fig5,
    pair: &CompatiblePair<Surd>,
    lam_l: &Surd,
) -> R<()> {
    let (case, text, src) = (f.case, f.text, &f.src);
    let id = |s: &str| f.id(s);
    let range = pair.admissible_rho_left().ok_or("range")?;
    let (klo, khi) = (lam_l.clone() * range.lo, lam_l.clone() * range.hi);
    let key = format!("fig5{case}_kappa_interval");
    if let Some(iv) = text["seed000"].get(&key) {
        let mut verdicts = Vec::new();
        for (i, end) in [&klo, &khi].into_iter().enumerate() {
            if let Some(sym) = iv["symbolic"][i].as_str() {
                verdicts.push((format!("end {i} {sym}"), judge(sym, end)));
            }
            if let Some(dec) = iv["decimal"][i].as_str() {
                verdicts.push((format!("end {i} ≈ {dec}"), judge(dec, end)));
            }
        }
        let bad: Vec<_> = verdicts
            .iter()
            .filter(|(_, (v, _))| *v != Verdict::Certified)
            .collect();
        let verdict = if bad.is_empty() {
            Verdict::Certified
        } else if bad.iter().any(|(_, (v, _))| *v == Verdict::Undecided) {
            Verdict::Undecided
        } else {
            Verdict::Erratum
        };
        let printed = iv.to_string();
        let wrong: Vec<String> = bad
            .iter()
            .map(|(w, (_, det))| format!("{w}: {det}"))
            .collect();
        out.push(Claim::new(
            &id("kappa-interval"),
            src,
            format!("κ may be chosen in {printed}"),
            verdict,
            format!(
                "engine: open interval ({}, {}); {}",
                show(&klo),
                show(&khi),
                wrong.join("; ")
            ),
        ));
    }
    Ok(())
}

/// The printed δ's of the two curves (κ the geometric mean).
fn fig5_deltas(out: &mut Vec<Claim>, f: &Fig5, ln: &LnPair<Surd>) {
    let (case, d, text, src) = (f.case, f.d, f.text, &f.src);
    let id = |s: &str| f.id(s);
    for (key, deltas) in [
        ("delta_l_printed", &ln.deltas_left),
        ("delta_r_printed", &ln.deltas_right),
    ] {
        let text_key = format!("fig5{case}_{}", key.trim_end_matches("_printed"));
        let Some(arr) = d.get(key).or_else(|| text["seed000"].get(&text_key)) else {
            continue;
        };
        for (i, dv) in [&deltas.0, &deltas.1].into_iter().enumerate() {
            let p = arr[i].as_str().unwrap_or_default();
            let (v, det) = judge(p, dv);
            let side = &key[6..7];
            out.push(Claim::new(
                &id(&format!("delta{side}{i}")),
                src,
                format!("δ{i}^{side} = {p}"),
                v,
                det,
            ));
        }
    }
}

/// The hodographs as printed, and b'l ∥ b'r.
fn fig5_hodographs(out: &mut Vec<Claim>, f: &Fig5, ln: &LnPair<Surd>) {
    let (case, d, text, src) = (f.case, f.d, f.text, &f.src);
    let id = |s: &str| f.id(s);
    let (lx, ly) = hodo(&ln.left);
    let (rx, ry) = hodo(&ln.right);
    let printed_hodo = [
        (
            "bl-prime",
            d.get("bl_prime_printed")
                .cloned()
                .or_else(|| text["seed000"].get(format!("fig5{case}_bl_prime")).cloned()),
            &lx,
            &ly,
        ),
        (
            "br-prime",
            d.get("br_prime_printed")
                .cloned()
                .or_else(|| text["seed000"].get(format!("fig5{case}_br_prime")).cloned()),
            &rx,
            &ry,
        ),
    ];
    for (name, pv, x, y) in printed_hodo {
        if let Some(p) = pv.as_ref().and_then(Value::as_str) {
            let (v, det) = judge_vector(p, x, y);
            out.push(Claim::new(
                &id(name),
                src,
                format!("{}'(t) = {p}", &name[..2]),
                v,
                det,
            ));
        }
    }
    // b'_l ∥ b'_r for all t: the cross product vanishes identically.
    let cross = lx.mul(&ry).sub(&ly.mul(&rx));
    let parallel = cross.coeffs().iter().all(|c| c.sign() == Sign::Zero);
    out.push(Claim::new(
        &id("parallel"),
        src,
        "b'l(t) ∥ b'r(t) for all t (one linear normal map)",
        if parallel {
            Verdict::Certified
        } else {
            Verdict::Refuted
        },
        "x'l y'r - y'l x'r is the zero polynomial (exact)",
    ));
}

/// The convolution's printed δ's and hodograph.
fn fig5_convolution(
    out: &mut Vec<Claim>,
    f: &Fig5,
    conv: &Convolution<Surd>,
    cx: &Poly<Surd>,
    cy: &Poly<Surd>,
) {
    let (case, d, text, src) = (f.case, f.d, f.text, &f.src);
    let id = |s: &str| f.id(s);
    if let Some(arr) = d.get("convolution_delta_printed") {
        for (i, dv) in [&conv.deltas.0, &conv.deltas.1].into_iter().enumerate() {
            let p = arr[i].as_str().unwrap_or_default();
            let (v, det) = judge(p, dv);
            out.push(Claim::new(
                &id(&format!("conv-delta{i}")),
                src,
                format!("convolution δ{i} = {p}"),
                v,
                det,
            ));
        }
    }
    if let Some(p) = text["seed000"]
        .get(format!("fig5{case}_conv_prime"))
        .and_then(Value::as_str)
    {
        let (v, det) = judge_vector(p, cx, cy);
        out.push(Claim::new(
            &id("conv-prime"),
            src,
            format!("(bl*br)'(t) = {p}"),
            v,
            det,
        ));
    }
}

/// Prop 4.4: the convolution's cusp, as printed, by the engine and directly.
fn fig5_cusp(
    out: &mut Vec<Claim>,
    f: &Fig5,
    conv: &Convolution<Surd>,
    cx: &Poly<Surd>,
    cy: &Poly<Surd>,
) {
    let (d, src) = (f.d, &f.src);
    let id = |s: &str| f.id(s);
    let printed_says = prop_4_4_as_printed(&conv.deltas);
    let engine_says = convolution_has_interior_cusp(&conv.deltas);
    let tau = cusp_parameter(&conv.deltas);
    let tau_txt = match &tau {
        Some(Tau::Finite(t)) => show(t),
        Some(Tau::Infinite) => "∞".into(),
        None => "?".into(),
    };
    // Direct check: the hodograph vanishes at τ (exact evaluation), or, for
    // rational curves, Sturm root isolation of gcd(x', y') on (0, 1).
    let direct = match &tau {
        Some(Tau::Finite(t)) => {
            let vanishes = cx.eval(t).sign() == Sign::Zero && cy.eval(t).sign() == Sign::Zero;
            let inside = t.sign() == Sign::Positive && Surd::one().cmp_sign(t) == Sign::Positive;
            Some(vanishes && inside)
        }
        Some(Tau::Infinite) => Some(false),
        None => None,
    };
    let rational_direct = to_rational_curve(&conv.curve)
        .and_then(|c| singular_points(&c, &Span::unit_open()))
        .map(|r| !r.is_empty());
    let direct = rational_direct.or(direct);
    let verdict = match (printed_says, engine_says, direct) {
        (Some(p), Some(e), Some(dr)) if p == e && e == dr => Verdict::Certified,
        (Some(_), Some(e), Some(dr)) if e == dr => Verdict::Erratum,
        _ => Verdict::Undecided,
    };
    out.push(Claim::new(
        &id("conv-cusp"),
        src,
        format!("Prop 4.4: the convolution has {} cusp in (0,1)", if printed_says == Some(true) { "a" } else { "no" }),
        verdict,
        format!("convolution δ = ({}, {}); cusp parameter τ = {tau_txt}; direct check (hodograph zero in (0,1)): {direct:?}", show(&conv.deltas.0), show(&conv.deltas.1)),
    ));
    if let (Some(p), Some(Tau::Finite(t))) = (
        d.get("convolution_cusp_tau_printed")
            .and_then(Value::as_str),
        &tau,
    ) {
        let (v, det) = judge(p, t);
        out.push(Claim::new(
            &id("cusp-tau"),
            src,
            format!("the convolution's cusp is at τ = {p}"),
            v,
            det,
        ));
    }
}

fn to_rational_curve(c: &Bezier<Surd>) -> Option<Bezier<Rational>> {
    let pts = c
        .points()
        .iter()
        .map(|p| Some(V2::new(p.x.as_rational()?, p.y.as_rational()?)))
        .collect::<Option<Vec<_>>>()?;
    Some(Bezier::new(pts))
}

fn fig4(out: &mut Vec<Claim>) -> R<()> {
    let text: Value = serde_json::from_str(data::TEXT).map_err(|e| e.to_string())?;
    let all: Value = serde_json::from_str(data::FIG5).map_err(|e| e.to_string())?;
    // Any non-collinear frame shows the claims; use Fig. 5(a)'s left frame.
    let f = frame(&all["a"]["left"])?;
    let f = LnFrame::<Rational>::new(
        f.b0.map(|v| v.as_rational().unwrap_or_default()),
        f.bm.map(|v| v.as_rational().unwrap_or_default()),
        f.b3.map(|v| v.as_rational().unwrap_or_default()),
    )
    .map_err(|e| e.to_string())?;
    for case in text["seed000"]["fig4"].as_array().ok_or("fig4")? {
        let cid = case["id"].as_str().unwrap_or("?");
        let rho = q(&case["kappa_over_lambda"])?;
        let (d0, d1) = deltas_from_rho(&rho).map_err(|e| e.to_string())?;
        let tau = tau_from_rho(&rho).ok_or("τ")?;
        let printed_tau = case["tau"].as_str().unwrap_or_default();
        let tau_ok = match (&tau, printed_tau) {
            (Tau::Infinite, "inf") => true,
            (Tau::Finite(t), p) => parse_rational(p).is_ok_and(|p| &p == t),
            _ => false,
        };
        let deltas_ok = q(&case["deltas"][0])? == d0 && q(&case["deltas"][1])? == d1;
        let curve = f.cubic(&d0, &d1);
        let sing = singular_points(&curve, &Span::unit_closed()).ok_or("hodograph ≡ 0")?;
        let sing_txt: Vec<String> = sing
            .iter()
            .map(|r| {
                if r.is_exact() {
                    r.lo.to_string()
                } else {
                    format!("[{}, {}]", r.lo, r.hi)
                }
            })
            .collect();
        // The singular points must be exactly {τ} ∩ [0, 1]: one isolating interval
        // containing τ, and the hodograph vanishing at τ exactly.
        let sing_ok = match &tau {
            Tau::Finite(t)
                if *t >= Rational::from_integer(0.into())
                    && *t <= Rational::from_integer(1.into()) =>
            {
                let h = curve.hodograph().eval(t);
                sing.len() == 1
                    && sing[0].lo <= *t
                    && *t <= sing[0].hi
                    && h.x == Rational::from_integer(0.into())
                    && h.y == Rational::from_integer(0.into())
            }
            _ => sing.is_empty(),
        };
        let ok = tau_ok && deltas_ok && sing_ok;
        out.push(Claim::new(
            &format!("000-fig4{cid}"),
            "seed 000 Fig. 4",
            format!("κ = {}·λ gives τ = {printed_tau}, [δ0, δ1] = {}; {}", case["kappa_over_lambda"].as_str().unwrap_or("?"), case["deltas"], case["claim"].as_str().unwrap_or("")),
            if ok { Verdict::Certified } else { Verdict::Erratum },
            format!("engine: [δ0, δ1] = [{d0}, {d1}], τ = {}; singular points in [0,1] by root isolation: {:?}", match &tau { Tau::Finite(t) => t.to_string(), Tau::Infinite => "∞".into() }, sing_txt),
        ));
    }
    Ok(())
}

/// Fig. 10: which of s1, s2 lie in (0,1) for three (α, κ), and the printed order.
fn fig10(out: &mut Vec<Claim>) -> R<()> {
    let text: Value = serde_json::from_str(data::TEXT).map_err(|e| e.to_string())?;
    let read_angle = |s: &str| -> Option<Interval> {
        if let Some(den) = s.strip_prefix("pi/") {
            let d: f64 = den.parse().ok()?;
            Some(Interval::PI / Interval::point(d)?)
        } else {
            Some(lncert::scalar::interval_from_rational(
                &parse_rational(s).ok()?,
            ))
        }
    };
    for (i, case) in text["seed000"]["fig10"]["cases"]
        .as_array()
        .ok_or("fig10")?
        .iter()
        .enumerate()
    {
        let first = case["first"].as_str().unwrap_or_default();
        let second = case["second"].as_str().unwrap_or_default();
        let expect: Vec<&str> = case["inside"]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_str).collect())
            .unwrap_or_default();
        let eval = |alpha: Interval, kappa: Interval| -> Option<(Vec<&'static str>, bool)> {
            let (s, c) = sin_cos_enclosure(alpha);
            let valid = alpha.inf() > 0.0
                // 2α < π, proven with an enclosure of π (not f64's π, which is below it).
                && (alpha + alpha).sup() < Interval::PI.inf()
                && kappa.inf() >= 0.5
                && kappa.sup() <= 2.0;
            let arc = ArcApprox::new(c, s, kappa).ok()?;
            let (in1, in2) = arc.params_in_unit()?;
            let mut v = Vec::new();
            if in1 {
                v.push("s1");
            }
            if in2 {
                v.push("s2");
            }
            Some((v, valid))
        };
        let (a, b) = (
            read_angle(first).ok_or("angle")?,
            read_angle(second).ok_or("angle")?,
        );
        let literal = eval(b, a); // printed as (κ, α) = (first, second)
        let swapped = eval(a, b); // read as (α, κ)
        let (verdict, detail) = match (&literal, &swapped) {
            (Some((v, true)), _) if *v == expect => (Verdict::Certified, format!("as printed (κ, α) = ({first}, {second}): inside (0,1): {v:?}")),
            (_, Some((v, true))) if *v == expect => (
                Verdict::Erratum,
                format!(
                    "read literally as (κ, α) = ({first}, {second}) the claim fails ({}); as (α, κ) = ({first}, {second}) — the order of Fig. 10's caption — it holds: inside (0,1): {v:?}",
                    match &literal { Some((v, ok)) => format!("inside {v:?}, within 0 < 2α < π and κ ∈ [1/2, 2]: {ok}"), None => "α outside 0 < 2α < π: the arc is undefined".into() }
                ),
            ),
            _ => (Verdict::Refuted, format!("literal: {literal:?}; swapped: {swapped:?}")),
        };
        out.push(Claim::new(
            &format!("000-fig10-{}", i + 1),
            "seed 000 Appendix (Fig. 9/10)",
            format!("for (κ, α) = ({first}, {second}) exactly {expect:?} lie in (0,1)"),
            verdict,
            detail,
        ));
    }
    Ok(())
}

pub(super) fn claims(out: &mut Vec<Claim>) {
    let parts: [(&str, ClaimGroup); 4] = [
        ("fig4", fig4),
        ("fig5a", |o| fig5(o, "a")),
        ("fig5b", |o| fig5(o, "b")),
        ("fig10", fig10),
    ];
    for (name, f) in parts {
        if let Err(e) = f(out) {
            out.push(Claim::new(
                &format!("000-{name}"),
                "seed 000",
                "built-in data",
                Verdict::Undecided,
                format!("error: {e}"),
            ));
        }
    }
}
