//! Density and temperature along x during the expansion, ensemble means of
//! the `temperature_x` slabs at a few multiples of the collisionless
//! relaxation time, beside the local adiabat (`theory::adiabat`): a fluid
//! in local equilibrium expanding without exchanging heat cools where it
//! has thinned, as n^(2/d) if ideal and more if dense. A collisionless gas
//! cools by sorting instead: the fast particles leave, and the slow ones
//! left behind are "cold" about their slab's mean.

use super::group::Group;
use crate::model::chart::{ChartSpec, Layer, colour};
use crate::model::report::Figure;
use crate::model::run_output::{RunOutput, Series};
use crate::stats::fill::fill;
use crate::stats::format::num;
use crate::stats::table::table_row;
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

/// One time's profile: slab centres, density over the final mean density,
/// kT over the start's, and the adiabat's kT at each slab's density.
struct Profile {
    t: f64,
    x: Vec<f64>,
    density: Vec<f64>,
    temperature: Vec<f64>,
    adiabat: Vec<f64>,
    /// The ideal gas's adiabat.
    ideal: Vec<f64>,
    /// Share of the kinetic energy not in the slabs' flow.
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
    let mut profiles = Vec::new();
    for k in TIMES {
        let want = k * tau;
        let i = times
            .iter()
            .position(|&t| t >= want - 1e-9)
            .unwrap_or(times.len() - 1);
        let mut density = Vec::new();
        let mut temperature = Vec::new();
        let mut adiabat = Vec::new();
        let mut ideal = Vec::new();
        let (mut thermal, mut total) = (0.0, 0.0);
        for (count, weight, sum) in &means {
            let (count, weight, sum) = (count[i].mean, weight[i].mean, sum[i].mean);
            let rel = count / slab_volume / gas.density;
            let kt = if weight > 0.0 { sum / weight } else { f64::NAN };
            density.push(rel);
            temperature.push(kt / kt0);
            // The start had density 2 n in the left half.
            let eta = gas.packing;
            adiabat.push(temperature_ratio(gas.dimension, 2.0 * eta, rel * eta));
            ideal.push((rel / 2.0).powf(2.0 / d));
            if kt.is_finite() {
                thermal += weight * kt;
            }
            total += count;
        }
        profiles.push(Profile {
            t: times[i],
            x: (0..slabs).map(|b| (b as f64 + 0.5) * width).collect(),
            density,
            temperature,
            adiabat,
            ideal,
            // d kT per particle's internal motion over d kT0 per particle.
            thermal_share: thermal / (total * kt0),
        });
    }
    let density = chart(
        &profiles,
        |p| &p.density,
        None,
        format!("Density along x during the expansion, {}", g.label()),
        "density n(x) / n̄ (n̄ of the gas filling the box)",
    );
    let temperature = chart(
        &profiles,
        |p| &p.temperature,
        Some(|p: &Profile| &p.adiabat),
        format!("Temperature along x during the expansion, {}", g.label()),
        "kT(x) / kT₀ about the slab's flow (dashed: the hard-particle adiabat)",
    );
    let (fd, ft) = (
        format!("expansion_density_{name}.svg"),
        format!("expansion_temperature_{name}.svg"),
    );
    let (l, r) = (slabs / 2 - 1, slabs / 2);
    let mut rows = String::new();
    for p in &profiles {
        let mut cells = vec![num(p.t), num(p.t / tau)];
        for b in [l, r] {
            cells.extend([p.density[b], p.temperature[b], p.adiabat[b], p.ideal[b]].map(num));
        }
        cells.push(num(p.thermal_share));
        rows.push_str(&table_row(&cells));
    }
    let md = fill(
        TEXT,
        &[
            ("name", name.into()),
            ("label", g.label()),
            ("times", TIMES.map(num).join(", ")),
            ("runs", g.outs.len().to_string()),
            ("density_file", fd.clone()),
            ("temperature_file", ft.clone()),
            ("rows", rows),
        ],
    );
    let figure = |file: String, chart| Figure { file, chart };
    Some((vec![figure(fd, density), figure(ft, temperature)], md))
}

fn chart(
    profiles: &[Profile],
    value: impl Fn(&Profile) -> &Vec<f64>,
    theory: Option<fn(&Profile) -> &Vec<f64>>,
    title: String,
    y_label: &str,
) -> ChartSpec {
    let mut layers = Vec::new();
    for (i, p) in profiles.iter().enumerate() {
        layers.push(Layer::Line {
            points: p.x.iter().copied().zip(value(p).iter().copied()).collect(),
            paint: colour(i),
            width: 2,
            dashed: false,
            label: Some(format!("t = {}", num(p.t))),
        });
        if let Some(f) = theory {
            layers.push(Layer::Line {
                points: p.x.iter().copied().zip(f(p).iter().copied()).collect(),
                paint: colour(i).faded(0.7),
                width: 1,
                dashed: true,
                label: None,
            });
        }
    }
    ChartSpec {
        title,
        x_label: "x [σ]".into(),
        y_label: y_label.into(),
        layers,
        ..Default::default()
    }
}
