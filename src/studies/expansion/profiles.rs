//! Density and temperature along x during the expansion, ensemble means of
//! the `temperature_x` slabs at a few multiples of the collisionless
//! relaxation time, beside the local adiabat (`theory::adiabat`): a fluid
//! in local equilibrium expanding without exchanging heat cools where it
//! has thinned, as n^(2/d) if ideal and more if dense. A collisionless gas
//! cools by sorting instead: the fast particles leave, and the slow ones
//! left behind are "cold" about their slab's mean.

use super::group::Group;
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::model::run_output::{RunOutput, Series};
use crate::stats::fill::fill;
use crate::stats::format::num;
use crate::stats::table::table_row;
use crate::studies::curves::{figure, polyline};
use crate::theory::adiabat::temperature_ratio;

const TEXT: &str = include_str!("profiles.md");

/// Per slab and sample, the weight (its count less one, 0 where its kT is
/// undefined) and the weighted kT, whose means over the runs pool the
/// slab's kT over the runs as if they were one gas.
const WEIGHT: &str = "pool_weight_x";
const SUM: &str = "pool_sum_x";

/// Add the pooling series to a run that recorded `temperature_x` (at run
/// time, where every run's series are at hand).
pub fn pool(out: &mut RunOutput) {
    let mut added = Vec::new();
    for b in 0.. {
        let (Some(c), Some(kt)) = (
            out.series(&format!("count_x.{b}")),
            out.series(&format!("temperature_x.{b}")),
        ) else {
            break;
        };
        let weight: Vec<f64> = c
            .value
            .iter()
            .zip(&kt.value)
            .map(|(c, kt)| if kt.is_finite() { c - 1.0 } else { 0.0 })
            .collect();
        let sum = weight
            .iter()
            .zip(&kt.value)
            .map(|(w, kt)| if *w > 0.0 { w * kt } else { 0.0 })
            .collect();
        for (name, value) in [(WEIGHT, weight), (SUM, sum)] {
            added.push(Series {
                observable: format!("{name}.{b}"),
                t: c.t.clone(),
                value,
            });
        }
    }
    out.series.extend(added);
}

/// The times shown, in collisionless relaxation times.
const TIMES: [f64; 5] = [0.0, 0.5, 1.0, 2.0, 4.0];

/// One time's profile: per slab the density over the final mean density,
/// kT over the start's, and the hard-particle and the ideal gas's adiabat
/// at the slab's density; and the share of the kinetic energy not in the
/// slabs' flow.
struct Profile {
    t: f64,
    slabs: Vec<[f64; 4]>,
    thermal_share: f64,
}

/// Figures and markdown for a case that recorded `temperature_x`; None
/// when it did not (or has no theory to scale time by).
pub fn section(g: &Group, name: &str) -> Option<(Vec<Figure>, String)> {
    let gas = g.gas.as_ref()?;
    let kt0 = gas.temperature(g.draw?);
    let tau = g.tau_free();
    let mean = |name: String| Some(g.mean_curve(&name)).filter(|(t, _)| !t.is_empty());
    let (times, _) = mean("count_x.0".into())?;
    let slabs = (0..)
        .take_while(|b| mean(format!("count_x.{b}")).is_some())
        .count();
    // Per slab, the means over the runs of the count and of the pooling
    // weights and sums (`pool`).
    let means = (0..slabs)
        .map(|b| {
            let at = |name: &str| mean(format!("{name}.{b}")).map(|(_, s)| s);
            Some((at("count_x")?, at(WEIGHT)?, at(SUM)?))
        })
        .collect::<Option<Vec<_>>>()?;
    let d = gas.dimension as f64;
    let width = gas.length / slabs as f64;
    let slab_volume = gas.volume() / slabs as f64;
    let x: Vec<f64> = (0..slabs).map(|b| (b as f64 + 0.5) * width).collect();
    let profile = |k: f64| {
        let i = (times.iter().position(|&t| t >= k * tau - 1e-9)).unwrap_or(times.len() - 1);
        let (mut thermal, mut total) = (0.0, 0.0);
        let slabs = (means.iter())
            .map(|(count, weight, sum)| {
                let (count, weight, sum) = (count[i].mean, weight[i].mean, sum[i].mean);
                let rel = count / slab_volume / gas.density;
                let kt = if weight > 0.0 { sum / weight } else { f64::NAN };
                if kt.is_finite() {
                    thermal += weight * kt;
                }
                total += count;
                // The start had density 2 n in the left half.
                let eta = gas.packing;
                let adiabat = temperature_ratio(gas.dimension, 2.0 * eta, rel * eta);
                [rel, kt / kt0, adiabat, (rel / 2.0).powf(2.0 / d)]
            })
            .collect();
        // d kT per particle's internal motion over d kT0 per particle.
        let thermal_share = thermal / (total * kt0);
        Profile {
            t: times[i],
            slabs,
            thermal_share,
        }
    };
    let profiles = TIMES.map(profile);
    let (fd, ft) = (
        format!("expansion_density_{name}.svg"),
        format!("expansion_temperature_{name}.svg"),
    );
    let label = g.label();
    let title = format!("Density along x during the expansion, {label}");
    let y_label = "density n(x) / n̄ (n̄ of the gas filling the box)";
    let density = chart(&fd, &profiles, &x, (0, None), (title, y_label));
    let title = format!("Temperature along x during the expansion, {label}");
    let y_label = "kT(x) / kT₀ about the slab's flow (dashed: the hard-particle adiabat)";
    let temperature = chart(&ft, &profiles, &x, (1, Some(2)), (title, y_label));
    let (l, r) = (slabs / 2 - 1, slabs / 2);
    let mut rows = String::new();
    for p in &profiles {
        let mut cells = vec![num(p.t), num(p.t / tau)];
        cells.extend([l, r].iter().flat_map(|&b| p.slabs[b].map(num)));
        cells.push(num(p.thermal_share));
        rows.push_str(&table_row(&cells));
    }
    let md = fill(
        TEXT,
        &[
            ("name", name.into()),
            ("label", label),
            ("times", TIMES.map(num).join(", ")),
            ("runs", g.outs.len().to_string()),
            ("density_file", fd),
            ("temperature_file", ft),
            ("rows", rows),
        ],
    );
    Some((vec![density, temperature], md))
}

/// The profiles' `value` (a column of their slabs) against x in `file`,
/// each beside its `theory` column, dashed, if it has one.
fn chart(
    file: &str,
    profiles: &[Profile],
    x: &[f64],
    (value, theory): (usize, Option<usize>),
    (title, y_label): (String, &str),
) -> Figure {
    let mut layers = Vec::new();
    for (i, p) in profiles.iter().enumerate() {
        let column = |k: usize| x.iter().zip(&p.slabs).map(|(x, s)| (*x, s[k])).collect();
        let label = Some(format!("t = {}", num(p.t)));
        layers.push(polyline(column(value), colour(i), 2, false, label));
        if let Some(k) = theory {
            layers.push(polyline(column(k), colour(i).faded(0.7), 1, true, None));
        }
    }
    figure(file, (title, "x [σ]", y_label), (false, false), layers)
}
