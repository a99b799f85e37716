//! Closed-form and asymptotic results: the references the BEM solver is tested
//! against, and answers in their own right where they are exact.
//!
//! | group | what | source |
//! |---|---|---|
//! | [`lambda`](mod@lambda) | `Lambda(u)`, `Lambda_g(t)`, the moments `a_m` | Perriot & Barthel (2004); Lyashenko, Popov & Borysiuk (2023) |
//! | [`series`] | flat punch and paraboloid on a layer over a rigid base: small-indentation series | Lyashenko, Popov & Borysiuk (2023); exact paraboloid series, compared with Dimitriadis et al. (2002) |
//! | [`BoussinesqPunch`], [`JkrFlatPunch`] | flat punch on a half-space, with Kendall adhesion | Boussinesq (1885); Kendall (1971) |
//! | [`Hertz`] | sphere (paraboloid) on a half-space | Hertz (1882); Johnson (1985) |
//! | [`JkrSphere`] | adhesive sphere on a half-space | Johnson, Kendall & Roberts (1971) |
//! | [`SneddonCone`] | conical punch on a half-space | Sneddon (1965) |
//! | [`JkrCone`] | adhesive cone on a half-space | Maugis & Barquins (1981) |
//! | [`JkrSinusoid`] | adhesive wavy surface on a half-space, plane strain | Westergaard (1939); Johnson (1995) |
//! | [`Axisymmetric`] | exact flat punch, paraboloid, sphere, cone and rounded cone ([`Tip`]), with JKR adhesion, on a coated half-space, by contact radius, depth or force | Fredholm equation, [`doc::axisymmetric`](crate::doc::axisymmetric) |
//! | [`LayeredJkrCycle`] | exact loading and unloading of a paraboloid with adhesion hysteresis | Johnson, Kendall & Roberts (1971); Maugis (2000) |
//!
//! The half-space solutions of the punch and the cone carry their authors'
//! names ([`BoussinesqPunch`], [`SneddonCone`]) so that they are not
//! confused with the indenter shapes [`indenter::FlatPunch`] and
//! [`indenter::Cone`] that the solver presses.
//!
//! [`indenter::FlatPunch`]: crate::indenter::FlatPunch
//! [`indenter::Cone`]: crate::indenter::Cone
//!
//! Every type here is built by a validating constructor (a typed
//! [`Error`](crate::Error) for bad input) and then evaluated by infallible
//! methods. The methods take the free variable (depth, contact radius, force)
//! as an `f64`: a NaN argument gives a NaN result, as for `f64::sqrt`.

pub mod axisymmetric;
pub mod lambda;
pub mod series;

mod cone;
mod hertz;
mod jkr;
mod layered_jkr;
mod layered_jkr_cycle;
mod layered_jkr_unloading;
mod punch;
mod sinusoid;

pub use axisymmetric::{
    before_jump_off, Axisymmetric, ContactState, ForceCurve, LayeredFlatPunch, LayeredParaboloid,
    LayeredTip, ModulusFamily, PullOff, Tip, MODULUS_NODES,
};
pub use cone::{JkrCone, SneddonCone};
pub use hertz::Hertz;
pub use jkr::JkrSphere;
pub use lambda::{a_m, a_m_of, lambda, lambda_g};
pub use layered_jkr_cycle::LayeredJkrCycle;
pub use punch::{BoussinesqPunch, JkrFlatPunch};
pub use series::{
    truncated_series, ConeForceSeries, ParaboloidForceSeries, PunchStiffnessSeries,
    SeriesStiffness, DIMITRIADIS_BONDED, DIMITRIADIS_UNBONDED, GARCIA_CONE, GARCIA_PARABOLOID,
    GARCIA_PUNCH,
};
pub use sinusoid::JkrSinusoid;

/// `x` clamped at zero from below, with NaN kept NaN (`f64::max` would turn
/// a NaN argument into 0, a silent wrong answer).
fn non_negative(x: f64) -> f64 {
    if x.is_nan() {
        x
    } else {
        x.max(0.0)
    }
}

/// The `a` in `[lo, hi]` where the rising `f` reaches `target` (`f(lo) <=
/// target <= f(hi)`), by bisection until the bracket stops shrinking (at
/// most 2100 halvings: f64's exponent range and mantissa).
fn rising_root(f: impl Fn(f64) -> f64, target: f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..2100 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if f(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
