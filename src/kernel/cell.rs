//! Closed-form integrals over rectangles `[0, X] x [0, Y]` ("corner
//! functions"). The integral over any axis-aligned cell follows by
//! inclusion-exclusion of its four corners, each function being odd in `X`
//! and in `Y`.

/// `Integral_0^X Integral_0^Y dx dy / sqrt(x^2 + y^2)
///  = X asinh(Y/X) + Y asinh(X/Y)`, Love (1929, Phil. Trans. R. Soc. A 228,
/// 377), for `X, Y >= 0` (0 if either is 0).
pub(crate) fn love(x: f64, y: f64) -> f64 {
    if x == 0.0 || y == 0.0 {
        return 0.0;
    }
    x * (y / x).asinh() + y * (x / y).asinh()
}

/// `Integral_0^X Integral_0^Y dx dy / sqrt(x^2 + y^2 + c^2)
///  = X asinh(Y / sqrt(X^2 + c^2)) + Y asinh(X / sqrt(Y^2 + c^2))
///    - c atan(X Y / (c sqrt(X^2 + Y^2 + c^2)))`,
/// the potential of a uniform rectangle at height `c` (differentiate in `X`
/// and `Y` to check), for `X, Y >= 0`, `c > 0`.
pub(crate) fn lifted_love(x: f64, y: f64, c: f64) -> f64 {
    if x == 0.0 || y == 0.0 {
        return 0.0;
    }
    let diagonal = (x * x + y * y + c * c).sqrt();
    x * (y / x.hypot(c)).asinh() + y * (x / y.hypot(c)).asinh()
        - c * (x * y / (c * diagonal)).atan()
}
