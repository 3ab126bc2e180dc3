//! The conduction part of the heat section: per point the mean profile
//! between the hot and the cold wall with the line through its middle, the
//! fluxes and the conductivity beside Chapman-Enskog and Enskog, the
//! temperature jumps; then κ over Chapman-Enskog's against the packing.

use super::section::{Runs, bar, dashed, figure, label, measured, with_z};
use super::{Gas, Line, Profile};
use crate::model::chart::{Layer, colour};
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::{Stats, z_score};
use crate::stats::table::table_row;
use crate::studies::curves::mean_with_band;
use crate::theory::heat::enskog_factor;

const TEXT: &str = include_str!("conduct.md");

/// Whether a jump is resolved above zero (z ≥ 4).
fn above_zero(s: &Stats) -> bool {
    z_score(s, 0.0).is_some_and(|z| z >= 4.0)
}

/// The runs' mean profile: the temperature's statistics per slab, and the
/// profile of their means (densities averaged, weights summed).
fn mean_profile(profiles: &[Profile]) -> (Vec<Stats>, Profile) {
    let bins = 0..profiles[0].x.len();
    let t_mean: Vec<Stats> = bins
        .clone()
        .map(|b| {
            let at = profiles.iter().map(|p| p.temperature[b]);
            Stats::of(&at.filter(|v| v.is_finite()).collect::<Vec<_>>())
        })
        .collect();
    let runs = profiles.len() as f64;
    let pooled = Profile {
        x: profiles[0].x.clone(),
        temperature: t_mean.iter().map(|s| s.mean).collect(),
        density: bins
            .clone()
            .map(|b| profiles.iter().map(|p| p.density[b]).sum::<f64>() / runs)
            .collect(),
        weight: bins
            .map(|b| profiles.iter().map(|p| p.weight[b]).sum())
            .collect(),
    };
    (t_mean, pooled)
}

/// `width`: the `fit_width` option.
pub fn part(
    width: f64,
    points: &[(Gas, (f64, f64, bool), Runs)],
    figures: &mut Vec<Figure>,
) -> String {
    let mut rows = String::new();
    let mut jumps = String::new();
    let (mut resolved, mut unresolved) = (Vec::new(), Vec::new());
    let mut pictures = String::new();
    let mut bars = Vec::new();
    for (k, (gas, (hot, cold, _), rs)) in points.iter().enumerate() {
        let name = label(rs, gas);
        let length = gas.size[0];
        let profiles: Vec<Profile> = rs
            .outs
            .iter()
            .filter_map(|o| Profile::of_run(gas, o))
            .collect();
        if profiles.is_empty() {
            continue;
        }
        let (t_mean, pooled) = mean_profile(&profiles);
        let line = Line::fit(&pooled, length, width);
        let phi = rs.stat("centre_packing");
        let centre_n = rs.stat("centre_density").mean;
        let ratio_0 = rs.stat("conductivity_ratio_dilute");
        if ratio_0.mean.is_finite() {
            bars.push(bar(phi.mean, &ratio_0));
        }
        let s = |name: &str| {
            let s = rs.stat(name);
            pm(s.mean, s.stderr)
        };
        let size: Vec<String> = gas.size.iter().map(|&l| num(l)).collect();
        rows.push_str(&table_row(&[
            name.clone(),
            size.join(" × "),
            format!("{} / {}", num(*hot), num(*cold)),
            rs.outs.len().to_string(),
            s("flux_in"),
            s("flux_out"),
            with_z(&rs.stat("flux_imbalance"), 0.0),
            pm(phi.mean, phi.stderr),
            num(gas.knudsen_at(centre_n)),
            s("conductivity"),
            num(rs.stat("conductivity_dilute").mean),
            num(rs.stat("conductivity_enskog").mean),
            with_z(&rs.stat("conductivity_ratio_enskog"), 1.0),
            pm(ratio_0.mean, ratio_0.stderr),
            num(rs.cpu()),
        ]));
        let (jh, jc) = (rs.stat("jump_hot"), rs.stat("jump_cold"));
        match above_zero(&jh) && above_zero(&jc) {
            true => resolved.push(name.clone()),
            false => unresolved.push(name.clone()),
        }
        let g = rs.stat("gradient");
        jumps.push_str(&table_row(&[
            name.clone(),
            pm(g.mean, g.stderr),
            with_z(&jh, 0.0),
            with_z(&jc, 0.0),
            num(jh.mean / g.mean.abs()),
            num(jc.mean / g.mean.abs()),
            num(gas.knudsen_at(centre_n) * length),
            count(rs.collisions()),
        ]));
        let (figure, text) = profile_figure(k, &points[k], width, &pooled, &t_mean, &line);
        figures.push(figure);
        pictures.push_str(&text);
    }
    let jumps_verdict = match (resolved.is_empty(), unresolved.is_empty()) {
        (_, true) => "Here it does at every point: each jump is more than 4 standard errors above zero.".into(),
        (true, false) => "Here no point resolves both jumps: each has one within 4 standard errors of zero, or below it.".into(),
        (false, false) => format!(
            "Here both jumps are more than 4 standard errors above zero at {}; at {} one is not resolved (within 4 standard errors of zero, or below it).",
            resolved.join("; "),
            unresolved.join("; ")
        ),
    };
    let conductivity_figure = if bars.is_empty() {
        String::new()
    } else {
        conductivity_chart(points[0].0.dimension, bars, figures)
    };
    fill(
        TEXT,
        &[
            ("pictures", pictures),
            ("rows", rows),
            ("jumps_verdict", jumps_verdict),
            ("jumps", jumps),
            ("conductivity_figure", conductivity_figure),
        ],
    )
}

/// The mean temperature across the box with the fitted line extended to
/// the walls, the walls' temperatures and the scaled density; the figure
/// and its Markdown.
fn profile_figure(
    k: usize,
    (gas, (hot, cold, hot_high), rs): &(Gas, (f64, f64, bool), Runs),
    width: f64,
    pooled: &Profile,
    t_mean: &[Stats],
    line: &Line,
) -> (Figure, String) {
    let (name, length) = (label(rs, gas), gas.size[0]);
    let file = format!("heat_profile_{k}.svg");
    let text = "temperature (mean ± standard error)".into();
    let mut layers = mean_with_band(&pooled.x, t_mean, colour(0), text).to_vec();
    let ends = [gas.diameter / 2.0, length - gas.diameter / 2.0];
    let text = format!("straight line through the middle {}%", num(100.0 * width));
    layers.push(dashed(
        ends.iter().map(|&x| (x, line.at(x))).collect(),
        colour(1),
        text,
    ));
    let (x_hot, x_cold) = if *hot_high {
        (length, 0.0)
    } else {
        (0.0, length)
    };
    layers.push(Layer::Markers {
        points: vec![(x_hot, *hot), (x_cold, *cold)],
        paint: colour(3),
        label: Some("wall temperatures".into()),
    });
    // Density on the same axis, scaled to the temperature's range.
    let n_max = pooled.density.iter().copied().fold(0.0, f64::max);
    if n_max > 0.0 {
        let scaled = pooled.x.iter().zip(&pooled.density);
        layers.push(Layer::Line {
            points: scaled.map(|(x, n)| (*x, n / n_max * hot)).collect(),
            paint: colour(2),
            width: 1,
            dashed: false,
            label: Some(format!(
                "density × {} (its maximum at kT_hot)",
                num(hot / n_max)
            )),
        });
    }
    let title = format!(
        "Steady profile between walls at kT = {} and {}, {name}",
        num(*hot),
        num(*cold)
    );
    let text = format!(
        "![{name}: temperature across the box (band: ±1 standard error over {} runs), the straight line fitted through its middle, extended to the walls (dashed: the gap to each wall's marker is the temperature jump), and the density profile, scaled.]({file})\n\n",
        rs.outs.len()
    );
    let axes = (title, "x [σ]", "kinetic temperature [kT]");
    (figure(&file, axes, (false, false), layers), text)
}

/// κ over Chapman-Enskog's against the packing at the centre, beside
/// Enskog's factor; the figure's Markdown.
fn conductivity_chart(
    dim: usize,
    bars: Vec<(f64, f64, f64, f64)>,
    figures: &mut Vec<Figure>,
) -> String {
    let top = bars.iter().map(|b| b.0).fold(0.0, f64::max) * 1.1;
    let file = "heat_conductivity.svg";
    let enskog = (0..=50)
        .map(|i| top * i as f64 / 50.0)
        .map(|p| (p, enskog_factor(dim, p)))
        .collect();
    let mut layers = vec![dashed(enskog, colour(1), "Enskog".into())];
    layers.extend(measured(
        bars,
        colour(0),
        "measured (mean ± standard error)",
    ));
    let title = "Thermal conductivity over the dilute (Chapman-Enskog) value".into();
    let axes = (
        title,
        "packing fraction at the centre φ",
        "κ / κ Chapman-Enskog",
    );
    figures.push(figure(file, axes, (false, false), layers));
    format!(
        "![The measured conductivity over Chapman-Enskog's at the centre's temperature, against the packing fraction there, beside Enskog's dense-gas factor (dashed).]({file})\n\n"
    )
}
