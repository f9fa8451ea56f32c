//! The flags whose value is one of a fixed set of names, as `clap` value
//! enums: clap rejects any other value as a usage error (exit 2, naming the
//! flag and listing the values), and each enum converts into the engine's
//! type. The engine reads no mode strings; the names are the CLI's.
//!
//! | enum | flags | values (aliases) |
//! |---|---|---|
//! | [`Method`] | `offset`, `convolve`, `stroke` `--method` | `g2`, `ln-pair` (`lnpair`) |
//! | [`Subdivision`] | `offset`, `convolve` `--subdivision` | `a` (`mid-angle`), `b` (`chord`), `c` (`weighted`) |
//! | [`Output`] | `offset`, `convolve`, `stroke` `--output` | `native`, `cubic`, `quadratic` (`quad`) |
//! | [`FontOutput`] | `font --output` | `cubic`, `quadratic` (`quad`) |
//! | [`Side`] | `convolve --side` | `plus` (`+`), `minus` (`-`), `both` |
//! | [`Accept`] | `convolve --accept` | `certified`, `paper` |
//! | [`Cap`] | `stroke --cap` | `round`, `butt` |
//! | [`Backend`] | `tangency --backend` | `complete`, `exact`, `cpu`, `gpu` (any case) |

use super::args::bad;
use super::CliError;
use clap::ValueEnum;
use lncert::offset::kernels as lnpair;

/// `--method`: the construction of the offset (or convolution) segments.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Seed 004 (seed 001 for convolutions): G²/C¹, degree n + 3.
    G2,
    /// Seed 000: cubic LN pairs.
    #[value(alias = "lnpair")]
    LnPair,
}

impl From<Method> for lncert::offset::OffsetMethod {
    fn from(m: Method) -> Self {
        match m {
            Method::G2 => lncert::offset::OffsetMethod::G2,
            Method::LnPair => lncert::offset::OffsetMethod::LnPair,
        }
    }
}

impl Method {
    /// The name on the command line (and in the JSON output).
    pub fn name(self) -> &'static str {
        lncert::offset::OffsetMethod::from(self).name()
    }
}

/// `--subdivision`: where an LN-pair span that missed the tolerance is split
/// (seed 000 §5's rules).
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Subdivision {
    /// (a) where the tangent bisects the end directions.
    #[value(name = "a", alias = "mid-angle")]
    MidAngle,
    /// (b) where the tangent is parallel to the approximant's chord.
    #[value(name = "b", alias = "chord")]
    Chord,
    /// (c) the angles of the two distances, weighted.
    #[value(name = "c", alias = "weighted")]
    Weighted,
}

impl From<Subdivision> for lnpair::Subdivision {
    fn from(s: Subdivision) -> Self {
        match s {
            Subdivision::MidAngle => lnpair::Subdivision::MidAngle,
            Subdivision::Chord => lnpair::Subdivision::Chord,
            Subdivision::Weighted => lnpair::Subdivision::Weighted,
        }
    }
}

impl Subdivision {
    /// The rule for `method`: a rule other than `a` needs `--method ln-pair`
    /// (G² spans are halved).
    pub fn for_method(self, method: Method) -> Result<lnpair::Subdivision, CliError> {
        if self != Subdivision::MidAngle && method != Method::LnPair {
            return Err(bad(
                "--subdivision",
                "the rules are seed 000 §5's, for LN pairs: use --method ln-pair (G² spans are halved)",
            ));
        }
        Ok(self.into())
    }
}

/// `--output`: the curves of the result.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// The construction's own segments.
    Native,
    /// Cubic Béziers fitted to the exact curve, proven.
    Cubic,
    /// Quadratic Béziers fitted to the exact curve, proven.
    #[value(alias = "quad")]
    Quadratic,
}

impl From<Output> for lncert::offset::Output {
    fn from(o: Output) -> Self {
        match o {
            Output::Native => lncert::offset::Output::Native,
            Output::Cubic => lncert::offset::Output::Cubic,
            Output::Quadratic => lncert::offset::Output::Quadratic,
        }
    }
}

/// `font --output`: the pieces written to the UFO.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FontOutput {
    /// Cubics (PostScript-style).
    Cubic,
    /// Quadratics (TrueType-style).
    #[value(alias = "quad")]
    Quadratic,
}

impl FontOutput {
    /// The name on the command line (and in the JSON summary).
    pub fn name(self) -> &'static str {
        match self {
            FontOutput::Cubic => "cubic",
            FontOutput::Quadratic => "quadratic",
        }
    }
}

/// `convolve --side`: which convolution curve.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The pen point whose outer normal is the trajectory's left normal.
    #[value(alias = "+")]
    Plus,
    /// The opposite pen point.
    #[value(alias = "-")]
    Minus,
    /// Both curves.
    Both,
}

impl Side {
    /// The sides to compute: the sign `σ` of each and its name.
    pub fn signs(self) -> Vec<(i8, &'static str)> {
        match self {
            Side::Plus => vec![(1, "plus")],
            Side::Minus => vec![(-1, "minus")],
            Side::Both => vec![(1, "plus"), (-1, "minus")],
        }
    }
}

/// `convolve --accept`: when a segment is accepted.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Accept {
    /// Its certified true error is ≤ T.
    Certified,
    /// Seed 000 §5's measure is ≤ T (LN pairs only).
    Paper,
}

impl Accept {
    /// The name on the command line (and in the JSON output).
    pub fn name(self) -> &'static str {
        match self {
            Accept::Certified => "certified",
            Accept::Paper => "paper",
        }
    }
}

/// `stroke --cap`: the end caps of an open curve.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cap {
    /// Half disks (half ellipses for an elliptical pen).
    Round,
    /// Straight segments across the ends.
    Butt,
}

impl From<Cap> for lncert::stroke::Cap {
    fn from(c: Cap) -> Self {
        match c {
            Cap::Round => lncert::stroke::Cap::Round,
            Cap::Butt => lncert::stroke::Cap::Butt,
        }
    }
}

/// `tangency --backend`: the solver.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Backend {
    /// The complete interval branch-and-prune solver.
    Complete,
    /// The exact elimination oracle.
    Exact,
    /// Raster candidates on the CPU, certified by Krawczyk.
    Cpu,
    /// Raster candidates on the GPU (the CPU without an adapter).
    Gpu,
}

impl Backend {
    /// A raster backend (`cpu` or `gpu`).
    pub fn is_raster(self) -> bool {
        matches!(self, Backend::Cpu | Backend::Gpu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_aliases() {
        let m = |s| Method::from_str(s, false);
        assert_eq!(m("lnpair"), Ok(Method::LnPair));
        assert_eq!(m("ln-pair").map(Method::name), Ok("ln-pair"));
        assert!(m("g3").is_err());
        assert_eq!(
            Subdivision::from_str("chord", false),
            Ok(Subdivision::Chord)
        );
        assert_eq!(Subdivision::from_str("c", false), Ok(Subdivision::Weighted));
        assert_eq!(Output::from_str("quad", false), Ok(Output::Quadratic));
        assert_eq!(Side::from_str("-", false), Ok(Side::Minus));
        assert_eq!(Backend::from_str("GPU", true), Ok(Backend::Gpu));
    }
}
