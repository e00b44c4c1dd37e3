//! The transcendental functions the physics and the seeded fills use, from
//! the `libm` crate: the same bits on every target (the standard library's
//! `sin`, `cos`, `powf` and `exp` call the platform's, which may differ in
//! the last bit between a desktop and a browser).

use glam::DVec2;

/// The unit vector at `angle` radians from +x.
pub fn unit(angle: f64) -> DVec2 {
    DVec2::new(libm::cos(angle), libm::sin(angle))
}

/// `x` to the power `y`.
pub fn pow(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// e to the power `x`.
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// The cube root of `x`.
pub fn cbrt(x: f64) -> f64 {
    libm::cbrt(x)
}

/// The arc cosine of `x` (radians).
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

/// The cosine of `x` (radians).
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agree_with_the_standard_library_to_an_ulp_or_two() {
        for k in 0..1000 {
            let a = k as f64 * 0.0123 - 6.0;
            let u = unit(a);
            assert!((u - DVec2::from_angle(a)).length() < 1e-15, "{a}");
            assert!((exp(a) / a.exp() - 1.0).abs() < 1e-15);
            assert!((pow(1.7, a) / 1.7f64.powf(a) - 1.0).abs() < 1e-15);
        }
    }
}
