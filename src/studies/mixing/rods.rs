//! One 1D run: rods between walls, all the kinetic energy started in one
//! particle (the scene's piston rod, the gas at rest). How long until the
//! energy is spread as equilibrium spreads it, and does it get there?

use crate::model::descriptor::Descriptor;
use crate::model::run_output::RunOutput;
use crate::scene::Built;
use crate::stats::late::late_mean;
use crate::stats::passage::first_passage;
use crate::studies::parts::scalars;
use crate::theory::mixing::equilibrium_concentration;

/// The largest over the smallest mass the descriptor lets the gas (every
/// species but the piston) draw, less one: 0 for equal masses.
pub fn mass_spread(d: &Descriptor) -> f64 {
    let Ok(scene) = crate::scene::resolve(&d.scene) else {
        return f64::NAN;
    };
    let bounds = scene
        .species
        .iter()
        .filter(|s| s.count > 0)
        .map(|s| s.mass.bounds());
    let (lo, hi) = bounds.fold((f64::INFINITY, 0.0f64), |(lo, hi), [a, b]| {
        (lo.min(a), hi.max(b))
    });
    hi / lo - 1.0
}

pub fn per_run(d: &Descriptor, built: &Built<1>, out: &mut RunOutput) -> Result<(), String> {
    if built.sim_box.axes[0].is_periodic() {
        // On a ring momentum is conserved too, and 3/(N + 2) no longer holds.
        return Err(
            "the mixing analysis in 1D needs walls: set scene.boundary = [\"walls\"] (its equilibrium assumes only the energy is conserved)"
                .into(),
        );
    }
    let n = built.particles.iter().filter(|p| !p.is_immovable()).count();
    // The hot rod's mass over the lightest mass the gas may draw (1 in the
    // bundled study): a property of the point, not of the draw.
    let lightest = crate::scene::resolve(&d.scene).map_or(f64::NAN, |s| {
        (s.species.iter().map(|k| k.mass.bounds()[0])).fold(f64::INFINITY, f64::min)
    });
    let hot_mass = built.piston.map_or(f64::NAN, |i| built.particles[i].mass());
    let y = out
        .series("energy_concentration")
        .ok_or("the mixing analysis needs the energy_concentration series")?;
    let (t, v) = (y.t.clone(), y.value.clone());
    let target = equilibrium_concentration(n);
    let tau = first_passage(&t, &v, target);
    let duration = t.last().copied().unwrap_or(f64::NAN) - t.first().copied().unwrap_or(f64::NAN);
    // Collisions per particle per unit time over the run: the clock that
    // makes times comparable across N and energies.
    let rate = 2.0 * out.collisions as f64 / (n as f64 * duration);
    let change = v.iter().map(|y| (y - v[0]).abs()).fold(0.0, f64::max);
    // The species that started with the most energy, against its
    // equipartition share (its count over N).
    let shares: Vec<_> = out
        .series
        .iter()
        .filter(|s| s.observable.starts_with("energy_share."))
        .collect();
    let hot = shares
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.value[0].total_cmp(&b.1.value[0]))
        .map(|(k, s)| {
            let count = built
                .particles
                .iter()
                .filter(|p| p.species as usize == k)
                .count();
            late_mean(&s.t, &s.value) / (count as f64 / n as f64)
        })
        .unwrap_or(f64::NAN);
    out.scalars.extend(scalars([
        ("particles", n as f64),
        ("mass_spread", mass_spread(d)),
        ("hot_mass_ratio", hot_mass / lightest),
        ("mixed", if tau.is_finite() { 1.0 } else { 0.0 }),
        ("mixing_time", tau),
        ("mixing_collisions", tau * rate),
        ("collision_rate", rate),
        ("late_concentration_ratio", late_mean(&t, &v) / target),
        ("concentration_change", change),
        ("hot_share_ratio", hot),
    ]));
    Ok(())
}
