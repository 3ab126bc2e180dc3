//! One 2D run. With walls along x (Imperial, "Mixing"): two species of
//! disks started in the left and the right half; how long until each is
//! spread over both halves? In a periodic box: the bulk fluid's
//! self-diffusion coefficient from the mean-squared displacement, which the
//! section turns into the diffusive prediction of the mixing time. (Not in
//! the mixing box itself: with walls along x and periodic y, shear modes
//! along y with wavelengths of the box length carry the disks collectively
//! and inflate the displacement along y several-fold in a dense strip.)

use crate::engine::boundary::ball_volume;
use crate::model::descriptor::Descriptor;
use crate::model::run_output::RunOutput;
use crate::scene::Built;
use crate::scene::velocities::maxwell_temperature;
use crate::stats::diffusion::diffusion;
use crate::stats::late::late_mean;
use crate::stats::passage::first_passage;
use crate::studies::parts::scalars;
use crate::theory::heat::mean_free_path;
use crate::theory::mixing::disk_mixture_diffusion_enskog;

/// kT of a Maxwellian start (the default when the scene gives none); None
/// for other velocity rules.
pub fn temperature(d: &Descriptor) -> Option<f64> {
    maxwell_temperature(crate::scene::resolve(&d.scene).ok()?.velocities.as_ref())
}

pub fn per_run(
    d: &Descriptor,
    built: &Built<2>,
    species: &[String],
    out: &mut RunOutput,
) -> Result<(), String> {
    let balls: Vec<_> = (built.particles.iter())
        .filter(|p| !p.is_immovable() && !p.is_plane())
        .collect();
    let n = balls.len();
    let count = |k: usize| balls.iter().filter(|p| p.species as usize == k).count();
    let mass = |k: usize| {
        let of_k = balls.iter().filter(|p| p.species as usize == k);
        of_k.map(|p| p.mass()).sum::<f64>() / count(k) as f64
    };
    let (na, nb) = (count(0), count(1));
    if na == 0 || nb == 0 || species.len() < 2 {
        return Err(
            "the mixing analysis in 2D needs two species (in a box with walls along x: the first started on the left, the second on the right)"
                .into(),
        );
    }
    let sizes = built.sim_box.size;
    let area = sizes[0] * sizes[1];
    let filled: f64 = balls.iter().map(|p| ball_volume(2, p.radius)).sum();
    let eta = filled / area;
    let density = n as f64 / area;
    let sigma = balls.iter().map(|p| 2.0 * p.radius).sum::<f64>() / n as f64;
    let (ma, mb) = (mass(0), mass(1));
    out.scalars.extend(scalars([
        ("particles", n as f64),
        ("packing_fraction", eta),
        ("mass_ratio", mb / ma),
        // Mean free path of the dilute gas over the box length along x.
        ("knudsen", mean_free_path(2, density, sigma) / sizes[0]),
    ]));
    let get = |name: String| {
        out.series(&name)
            .cloned()
            .ok_or(format!("the mixing analysis needs the series `{name}`"))
    };
    let axes = &built.sim_box.axes;
    if !axes[0].is_periodic() {
        // Walls along x: the two species started apart, mixing.
        let a_left = get(format!("count.{}.left", species[0]))?;
        let b_right = get(format!("count.{}.right", species[1]))?;
        let t = a_left.t.clone();
        // The fraction of the disks still in the half they started in.
        let own: Vec<f64> = a_left
            .value
            .iter()
            .zip(&b_right.value)
            .map(|(a, b)| 0.5 * (a / na as f64 + b / nb as f64))
            .collect();
        let tau = first_passage(&t, &own, 0.5);
        let a_fraction: Vec<f64> = a_left.value.iter().map(|a| a / na as f64).collect();
        out.scalars.extend(scalars([
            ("mixed", if tau.is_finite() { 1.0 } else { 0.0 }),
            ("mixing_time", tau),
            ("late_left_fraction", late_mean(&t, &a_fraction)),
        ]));
    } else if axes.iter().all(|a| a.is_periodic()) {
        // A periodic box: the bulk fluid's self-diffusion, over both axes
        // and both species (count-weighted: with equal counts, Darken's
        // estimate of the interdiffusion coefficient, exact when the species
        // differ only by colour).
        let mut total = 0.0;
        let mut from = f64::NAN;
        for k in 0..2 {
            for axis in ["x", "y"] {
                let msd = get(format!("msd.{}.{axis}", species[k]))?;
                let (dk, start) = diffusion(&msd.t, &msd.value);
                total += 0.5 * count(k) as f64 * dk;
                from = start;
            }
        }
        let dmix = total / n as f64;
        let kt = temperature(d).unwrap_or(f64::NAN);
        // Enskog for equal disks, each pair moving with its reduced mass.
        let one_size = balls.iter().all(|p| p.radius == balls[0].radius);
        let x = [na, nb].map(|c| c as f64 / n as f64);
        let enskog = if one_size {
            disk_mixture_diffusion_enskog(density, sigma, kt, [ma, mb], x, eta)
        } else {
            f64::NAN
        };
        // How many velocity memory times (D m / kT) in the fit starts.
        let memory = from / (dmix * 0.5 * (ma + mb) / kt);
        out.scalars.extend(scalars([
            ("diffusion", dmix),
            ("diffusion_enskog", enskog),
            ("diffusion_ratio", dmix / enskog),
            ("memory_ratio", memory),
        ]));
    }
    Ok(())
}
