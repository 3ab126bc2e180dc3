//! Vectors in D dimensions: plain arrays, so the dimension is a const generic
//! and nothing below assumes 2D or 3D.

pub type Vector<const D: usize> = [f64; D];

#[inline(always)]
pub fn dot<const D: usize>(a: &Vector<D>, b: &Vector<D>) -> f64 {
    let mut s = 0.0;
    for k in 0..D {
        s += a[k] * b[k];
    }
    s
}

#[inline(always)]
pub fn sub<const D: usize>(a: &Vector<D>, b: &Vector<D>) -> Vector<D> {
    std::array::from_fn(|k| a[k] - b[k])
}

#[inline(always)]
pub fn add_scaled<const D: usize>(a: &Vector<D>, s: f64, b: &Vector<D>) -> Vector<D> {
    std::array::from_fn(|k| a[k] + s * b[k])
}

#[inline(always)]
pub fn norm2<const D: usize>(a: &Vector<D>) -> f64 {
    dot(a, a)
}

/// The axis-0 part of a vector: all that a plane perpendicular to axis 0 sees.
#[inline(always)]
pub fn axis0<const D: usize>(a: &Vector<D>) -> Vector<D> {
    std::array::from_fn(|k| if k == 0 { a[0] } else { 0.0 })
}
