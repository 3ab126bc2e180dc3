//! The collision rule on its own: conservation, the special cases, and the 1D
//! map as a reflection (MacKay's follow-up question).

use crate::common;

use bonkers::engine::collide::{bounce, contact_time};
use rand::RngExt;

fn check_conservation<const D: usize>(seed: u64) {
    let mut rng = common::rng(seed);
    for _ in 0..10_000 {
        // Masses over 24 decades, and now and then an infinite one.
        let im: [f64; 2] = std::array::from_fn(|_| {
            if rng.random::<f64>() < 0.05 {
                0.0
            } else {
                10f64.powf(rng.random::<f64>() * 24.0 - 12.0)
            }
        });
        if im[0] == 0.0 && im[1] == 0.0 {
            continue;
        }
        // Immovable particles are at rest (the engine refuses moving ones).
        let vi: [f64; D] = std::array::from_fn(|_| {
            if im[0] == 0.0 {
                0.0
            } else {
                common::gaussian(&mut rng)
            }
        });
        let vj: [f64; D] = std::array::from_fn(|_| {
            if im[1] == 0.0 {
                0.0
            } else {
                common::gaussian(&mut rng)
            }
        });
        let raw: [f64; D] = std::array::from_fn(|_| common::gaussian(&mut rng));
        let len = raw.iter().map(|x| x * x).sum::<f64>().sqrt();
        let n: [f64; D] = std::array::from_fn(|k| raw[k] / len);
        let Some(b) = bounce(&vi, &vj, im[0], im[1], &n) else {
            continue;
        };
        let wi: [f64; D] = std::array::from_fn(|k| vi[k] + b.dv_i[k]);
        let wj: [f64; D] = std::array::from_fn(|k| vj[k] + b.dv_j[k]);
        let ke = |v: &[f64; D], im: f64| {
            if im == 0.0 {
                0.0
            } else {
                0.5 * v.iter().map(|x| x * x).sum::<f64>() / im
            }
        };
        let (e0, e1) = (
            ke(&vi, im[0]) + ke(&vj, im[1]),
            ke(&wi, im[0]) + ke(&wj, im[1]),
        );
        // Energy, relative to the larger of the two bodies' energies.
        let scale = ke(&vi, im[0])
            .max(ke(&vj, im[1]))
            .max(ke(&wi, im[0]))
            .max(ke(&wj, im[1]));
        assert!((e1 - e0).abs() <= 1e-13 * scale, "energy {e0} -> {e1}");
        // Momentum of finite masses equals the impulse balance exactly in form;
        // check the impulse on i is what its velocity change implies.
        if im[0] > 0.0 {
            for k in 0..D {
                // Round-off in w - v is relative to the momentum itself.
                let dp = (wi[k] - vi[k]) / im[0];
                let scale = b.impulse_i[k]
                    .abs()
                    .max(vi[k].abs() / im[0])
                    .max(wi[k].abs() / im[0]);
                assert!((dp - b.impulse_i[k]).abs() <= 1e-13 * scale.max(1e-300));
            }
        }
        if im[0] > 0.0 && im[1] > 0.0 {
            for k in 0..D {
                let (p0, p1) = (vi[k] / im[0] + vj[k] / im[1], wi[k] / im[0] + wj[k] / im[1]);
                let s = (vi[k] / im[0])
                    .abs()
                    .max((vj[k] / im[1]).abs())
                    .max((wi[k] / im[0]).abs());
                assert!(
                    (p1 - p0).abs() <= 1e-13 * s.max(1e-300),
                    "momentum {p0} -> {p1}"
                );
            }
        }
        // Afterwards the pair recedes along the line of centres.
        let u_after: f64 = (0..D).map(|k| (wi[k] - wj[k]) * n[k]).sum();
        assert!(u_after <= 0.0);
    }
}

#[test]
fn random_pairs_conserve_energy_and_momentum_1d_2d_3d() {
    check_conservation::<1>(1);
    check_conservation::<2>(2);
    check_conservation::<3>(3);
}

#[test]
fn equal_masses_swap_velocities_in_1d() {
    let b = bounce(&[1.5], &[-0.25], 1.0, 1.0, &[1.0]).unwrap();
    assert_eq!(1.5 + b.dv_i[0], -0.25);
    assert_eq!(-0.25 + b.dv_j[0], 1.5);
}

#[test]
fn an_immovable_partner_reflects_like_a_wall() {
    let b = bounce(&[0.3, 2.0], &[0.0, 0.0], 1.0, 0.0, &[0.0, 1.0]).unwrap();
    assert_eq!(b.dv_j, [0.0, 0.0]);
    assert_eq!([0.3 + b.dv_i[0], 2.0 + b.dv_i[1]], [0.3, -2.0]);
}

#[test]
fn receding_pairs_never_collide() {
    assert!(bounce(&[-1.0], &[1.0], 1.0, 1.0, &[1.0]).is_none());
    // Overlapping but receding (the sticking bug): no contact predicted.
    assert_eq!(contact_time(&[0.5, 0.0], &[1.0, 0.0], 1.0), None);
    // Overlapping by round-off and approaching: collide now.
    assert_eq!(
        contact_time(&[1.0 - 1e-15, 0.0], &[-1.0, 0.0], 1.0),
        Some(0.0)
    );
}

/// The 1D collision is the linear map v -> A v with A = [[a, 1-a], [1+a... ]];
/// build it column by column and check A^2 = I, eigenvalue +1 on the common
/// velocity (1, 1) and -1 on the zero-momentum direction (1/m1, -1/m2).
#[test]
fn the_1d_collision_map_is_a_reflection() {
    let (im1, im2) = (1.0 / 3.0, 1.0 / 7.0);
    let map = |u: [f64; 2]| -> [f64; 2] {
        // The map is linear even for receding inputs; apply the formula directly.
        let c = (im2 * u[0] + im1 * u[1]) / (im1 + im2);
        [2.0 * c - u[0], 2.0 * c - u[1]]
    };
    // It agrees with the engine's rule on approaching inputs.
    let b = bounce(&[1.0], &[-0.5], im1, im2, &[1.0]).unwrap();
    let m = map([1.0, -0.5]);
    assert!((1.0 + b.dv_i[0] - m[0]).abs() < 1e-15 && (-0.5 + b.dv_j[0] - m[1]).abs() < 1e-15);
    let col0 = map([1.0, 0.0]);
    let col1 = map([0.0, 1.0]);
    let a = [[col0[0], col1[0]], [col0[1], col1[1]]];
    let trace = a[0][0] + a[1][1];
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    assert!(trace.abs() < 1e-15, "eigenvalues sum to 0: {trace}");
    assert!(
        (det + 1.0).abs() < 1e-15,
        "eigenvalues multiply to -1: {det}"
    );
    let plus = map([1.0, 1.0]);
    assert!((plus[0] - 1.0).abs() < 1e-15 && (plus[1] - 1.0).abs() < 1e-15);
    let minus = map([im1, -im2]);
    assert!((minus[0] + im1).abs() < 1e-15 && (minus[1] - im2).abs() < 1e-15);
    let twice = map(map([0.3, -1.7]));
    assert!((twice[0] - 0.3).abs() < 1e-15 && (twice[1] + 1.7).abs() < 1e-15);
}
