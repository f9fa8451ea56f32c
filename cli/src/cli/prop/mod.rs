//! `lncert prop ID [ARGS] [--json]`: one proposition of a seed on user data.
//!
//! IDs are `SEED:PROP` (`003:2.1`, `000:4.4`, ...); the seed may be left out
//! when the number is unambiguous (`3.1` and `6.1` exist in both seeds and must
//! be qualified). Each handler reads only its own flags and rejects the others.
//!
//! | module | propositions |
//! |---|---|
//! | [`seed003`] | 003: Props 2.1, 3.1/3.2, 3.3, 6.1, 7.1 (normal form `K = [-f', -f + t f']`) |
//! | [`seed000`] | 000: Prop 3.1, Lemma 4.1, Prop 4.2, Remark 4.3, Prop 4.4 (cubic LN frames) |
//! | [`circle`] | 000: Prop 6.1 (circular arc approximation) |

pub mod circle;
pub mod seed000;
pub mod seed003;

use super::args::bad;
use super::report::Report;
use super::CliError;

/// Arguments of `lncert prop`. Every number is read exactly (`0.95` is 19/20,
/// `1/3` is 1/3); values may start with `-` (`--y1 -1`, `--b0 -1,2`).
#[derive(clap::Args, Debug, Default)]
pub struct PropArgs {
    /// Proposition ID: 2.1, 3.2, 3.3, 7.1, 4.1, 4.2, 4.3, 4.4, or qualified
    /// 003:3.1, 000:3.1, 003:6.1, 000:6.1 (any ID may be qualified).
    #[arg(value_name = "ID")]
    pub id: String,
    /// End point x of the Hermite data [x1, y1] (seed 003).
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub x1: Option<String>,
    /// End point y of the Hermite data (seed 003).
    #[arg(long, value_name = "Y", allow_hyphen_values = true)]
    pub y1: Option<String>,
    /// End normal (u, 1) and parameter interval [0, u] (seed 003).
    #[arg(long, value_name = "U", allow_hyphen_values = true)]
    pub u: Option<String>,
    /// Free coefficient a2 of the quartic interpolant (seed 003 Prop 3.2).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub a2: Option<String>,
    /// Slope m of the tangent line m x + y + b = 0, 0 < m < u (seed 003 Prop 3.3).
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub m: Option<String>,
    /// Intercept b of the tangent line (seed 003 Prop 3.3).
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub b: Option<String>,
    /// Power coefficients c0,c1,... of f (seed 003 Prop 6.1).
    #[arg(long, value_name = "C0,C1,...", allow_hyphen_values = true)]
    pub f: Option<String>,
    /// Power coefficients c0,c1,... of g (seed 003 Prop 6.1).
    #[arg(long, value_name = "C0,C1,...", allow_hyphen_values = true)]
    pub g: Option<String>,
    /// Cusp parameter τ (a number or `inf`).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub tau: Option<String>,
    /// LN frame `b0x,b0y;bmx,bmy;b3x,b3y`.
    #[arg(long, value_name = "FRAME", allow_hyphen_values = true)]
    pub frame: Option<String>,
    /// ρ = κ/λ (Lemma 4.1), or κ/λl for a pair (Props 4.2–4.4).
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub rho: Option<String>,
    /// Left frame of a compatible pair.
    #[arg(long, value_name = "FRAME", allow_hyphen_values = true)]
    pub left: Option<String>,
    /// Right frame of a compatible pair.
    #[arg(long, value_name = "FRAME", allow_hyphen_values = true)]
    pub right: Option<String>,
    /// Half-angle α of the arc in radians (enclosed rigorously; seed 000 Prop 6.1).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub alpha: Option<String>,
    /// cos α, exact (with --sin; cos² + sin² = 1).
    #[arg(long, value_name = "C", allow_hyphen_values = true)]
    pub cos: Option<String>,
    /// sin α, exact (with --cos).
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub sin: Option<String>,
    /// κ of the normal map N0 (1-t) + κ N1 t (seed 000 Prop 6.1).
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub kappa: Option<String>,
    /// Print one JSON document instead of text.
    #[arg(long)]
    pub json: bool,
}

impl PropArgs {
    /// Every value flag with whether it was given.
    pub fn given(&self) -> Vec<(&'static str, bool)> {
        let all = [
            ("--x1", &self.x1),
            ("--y1", &self.y1),
            ("--u", &self.u),
            ("--a2", &self.a2),
            ("--m", &self.m),
            ("--b", &self.b),
            ("--f", &self.f),
            ("--g", &self.g),
            ("--tau", &self.tau),
            ("--frame", &self.frame),
            ("--rho", &self.rho),
            ("--left", &self.left),
            ("--right", &self.right),
            ("--alpha", &self.alpha),
            ("--cos", &self.cos),
            ("--sin", &self.sin),
            ("--kappa", &self.kappa),
        ];
        all.into_iter().map(|(k, v)| (k, v.is_some())).collect()
    }
    /// Rejects every flag not in `allowed`.
    pub fn only(&self, id: &str, usage: &str, allowed: &[&str]) -> Result<(), CliError> {
        super::args::reject_unused(id, usage, allowed, &self.given())
    }
}

/// A handler: checks the flags, computes, and returns the report.
type Handler = fn(&PropArgs, &'static str) -> Result<Report, CliError>;

/// Every proposition: (qualified ID `seed:number`, description, handler).
const PROPS: &[(&str, &str, Handler)] = &[
    (
        "003:2.1",
        "cubic Hermite interpolant: nonsingular u-range",
        seed003::prop_2_1,
    ),
    (
        "003:3.1",
        "a nonsingular quartic Hermite interpolant exists",
        seed003::prop_3_2,
    ),
    (
        "003:3.2",
        "the a2-interval of nonsingular quartics",
        seed003::prop_3_2,
    ),
    (
        "003:3.3",
        "quartic tangent to a line m x + y + b = 0",
        seed003::prop_3_3,
    ),
    (
        "003:6.1",
        "convolution of normal-form curves",
        seed003::prop_6_1,
    ),
    (
        "003:7.1",
        "general-interval cubic: recommended τ",
        seed003::prop_7_1,
    ),
    (
        "000:3.1",
        "cubic LN curve with cusp parameter τ",
        seed000::prop_3_1,
    ),
    (
        "000:4.1",
        "Lemma 4.1: regular iff κ/λ ∈ (1/2, 2)",
        seed000::lemma_4_1,
    ),
    (
        "000:4.2",
        "compatible pair with one linear normal map",
        seed000::prop_4_2,
    ),
    (
        "000:4.3",
        "Remark 4.3: extended linear normal map",
        seed000::prop_4_2,
    ),
    (
        "000:4.4",
        "cusp of the convolution of a pair",
        seed000::prop_4_4,
    ),
    (
        "000:6.1",
        "cubic LN approximation of a circular arc",
        circle::prop_6_1,
    ),
];

/// Finds the proposition for an ID (`3.2` or `003:3.2`); ambiguous or unknown
/// IDs are bad input listing the choices.
pub fn resolve(id: &str) -> Result<(&'static str, Handler), CliError> {
    let id = id.trim();
    let matches = |q: &str| {
        if id.contains(':') {
            q == id
        } else {
            q.split_once(':').is_some_and(|(_, n)| n == id)
        }
    };
    let hits: Vec<_> = PROPS.iter().filter(|p| matches(p.0)).collect();
    match hits.as_slice() {
        [one] => Ok((one.0, one.2)),
        [] => Err(bad(
            "ID",
            format!(
                "unknown proposition {id:?}; known: {}",
                choices(PROPS.iter())
            ),
        )),
        many => Err(bad(
            "ID",
            format!(
                "{id:?} is ambiguous, qualify it with the seed: {}",
                choices(many.iter().copied())
            ),
        )),
    }
}

fn choices<'a>(it: impl Iterator<Item = &'a (&'static str, &'static str, Handler)>) -> String {
    it.map(|p| format!("{} ({})", p.0, p.1))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Runs `lncert prop`; returns the exit code.
pub fn run(a: &PropArgs) -> Result<i32, CliError> {
    let (id, handler) = resolve(&a.id)?;
    let report = handler(a, id)?;
    Ok(report.emit(a.json))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_resolve_and_ambiguity_is_reported() {
        assert_eq!(resolve("2.1").unwrap().0, "003:2.1");
        assert_eq!(resolve("000:3.1").unwrap().0, "000:3.1");
        assert_eq!(resolve("003:6.1").unwrap().0, "003:6.1");
        assert_eq!(resolve("4.4").unwrap().0, "000:4.4");
        let e = resolve("3.1").unwrap_err().to_string();
        assert!(
            e.contains("ambiguous") && e.contains("000:3.1") && e.contains("003:3.1"),
            "{e}"
        );
        assert!(resolve("9.9").unwrap_err().to_string().contains("unknown"));
        assert!(resolve("000:2.1").is_err());
    }
}
