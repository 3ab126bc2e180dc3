//! The conduction part of the heat section: per point the mean profile
//! between the hot and the cold wall with the line through its middle, the
//! fluxes and the conductivity beside Chapman-Enskog and Enskog, the
//! temperature jumps; then κ over Chapman-Enskog's against the packing.

use super::section::{CAPTIONS, Runs, bar, dashed, figure, label, measured, with_z};
use super::{Gas, Line, Profile};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num, pm};
use crate::stats::named::named;
use crate::stats::summary::{Stats, z_score};
use crate::stats::table::table_row;
use crate::studies::curves::{markers, mean_with_band, polyline, sampled, show};
use crate::studies::parts::stat_pm;
use crate::theory::heat::enskog_factor;

const TEXT: &str = include_str!("conduct.md");

/// Whether a jump is resolved above zero (z ≥ 4).
fn above_zero(s: &Stats) -> bool {
    z_score(s, 0.0).is_some_and(|z| z >= 4.0)
}

/// The runs' mean profile: the temperature's statistics per slab, and the
/// profile of their means (densities averaged, weights summed).
fn mean_profile(profiles: &[Profile]) -> (Vec<Stats>, Profile) {
    // Per slab, one of the profiles' columns over the runs.
    let per_slab = |column: fn(&Profile) -> &[f64]| {
        (0..profiles[0].x.len()).map(move |b| profiles.iter().map(move |p| column(p)[b]))
    };
    let t_mean: Vec<Stats> = per_slab(|p| &p.temperature)
        .map(|at| Stats::of(&at.filter(|v| v.is_finite()).collect::<Vec<_>>()))
        .collect();
    let runs = profiles.len() as f64;
    let pooled = Profile {
        x: profiles[0].x.clone(),
        temperature: t_mean.iter().map(|s| s.mean).collect(),
        density: per_slab(|p| &p.density)
            .map(|at| at.sum::<f64>() / runs)
            .collect(),
        weight: per_slab(|p| &p.weight).map(|at| at.sum()).collect(),
    };
    (t_mean, pooled)
}

/// `width`: the `fit_width` option.
pub fn part(
    width: f64,
    points: &[(Gas, (f64, f64, bool), Runs)],
    figures: &mut Vec<Figure>,
) -> String {
    let (mut rows, mut jumps, mut pictures) = (String::new(), String::new(), String::new());
    let (mut resolved, mut unresolved, mut bars) = (Vec::new(), Vec::new(), Vec::new());
    for (k, point) in points.iter().enumerate() {
        let (gas, (hot, cold, _), rs) = point;
        let name = label(rs, gas);
        let profiles: Vec<Profile> = (rs.outs.iter())
            .filter_map(|o| Profile::of_run(gas, o))
            .collect();
        if profiles.is_empty() {
            continue;
        }
        let phi = rs.stat("centre_packing");
        let kn = gas.knudsen_at(rs.stat("centre_density").mean);
        let ratio_0 = rs.stat("conductivity_ratio_dilute");
        if ratio_0.mean.is_finite() {
            bars.push(bar(phi.mean, &ratio_0));
        }
        let size: Vec<String> = gas.size.iter().map(|&l| num(l)).collect();
        rows.push_str(&table_row(&[
            name.clone(),
            size.join(" × "),
            format!("{} / {}", num(*hot), num(*cold)),
            rs.outs.len().to_string(),
            stat_pm(rs, "flux_in"),
            stat_pm(rs, "flux_out"),
            with_z(&rs.stat("flux_imbalance"), 0.0),
            pm(phi.mean, phi.stderr),
            num(kn),
            stat_pm(rs, "conductivity"),
            num(rs.stat("conductivity_dilute").mean),
            num(rs.stat("conductivity_enskog").mean),
            with_z(&rs.stat("conductivity_ratio_enskog"), 1.0),
            pm(ratio_0.mean, ratio_0.stderr),
            num(rs.cpu()),
        ]));
        let (jh, jc, g) = (
            rs.stat("jump_hot"),
            rs.stat("jump_cold"),
            rs.stat("gradient"),
        );
        match above_zero(&jh) && above_zero(&jc) {
            true => resolved.push(name.clone()),
            false => unresolved.push(name.clone()),
        }
        jumps.push_str(&table_row(&[
            name,
            pm(g.mean, g.stderr),
            with_z(&jh, 0.0),
            with_z(&jc, 0.0),
            num(jh.mean / g.mean.abs()),
            num(jc.mean / g.mean.abs()),
            num(kn * gas.size[0]),
            count(rs.collisions()),
        ]));
        pictures.push_str(&profile_figure(k, point, width, &profiles, figures));
    }
    let verdict = match (resolved.is_empty(), unresolved.is_empty()) {
        (_, true) => "jumps_all",
        (true, false) => "jumps_none",
        (false, false) => "jumps_some",
    };
    let verdict_values = [
        ("resolved", resolved.join("; ")),
        ("unresolved", unresolved.join("; ")),
    ];
    let mut conductivity_figure = String::new();
    if !bars.is_empty() {
        // κ over Chapman-Enskog's against the packing, beside Enskog's factor.
        let (dim, top) = (
            points[0].0.dimension,
            bars.iter().map(|b| b.0).fold(0.0, f64::max),
        );
        let enskog = sampled(0.0, top * 1.1, 50, |p| enskog_factor(dim, p));
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
        let figure = figure("heat_conductivity.svg", axes, (false, false), layers);
        conductivity_figure = show(figures, figure, named(CAPTIONS, "conductivity"));
    }
    fill(
        TEXT,
        &[
            ("pictures", pictures),
            ("rows", rows),
            (
                "jumps_verdict",
                fill(named(CAPTIONS, verdict), &verdict_values),
            ),
            ("jumps", jumps),
            ("conductivity_figure", conductivity_figure),
        ],
    )
}

/// The mean temperature across the box with the fitted line extended to
/// the walls, the walls' temperatures and the scaled density; the figure's
/// Markdown.
fn profile_figure(
    k: usize,
    (gas, (hot, cold, hot_high), rs): &(Gas, (f64, f64, bool), Runs),
    width: f64,
    profiles: &[Profile],
    figures: &mut Vec<Figure>,
) -> String {
    let (name, length) = (label(rs, gas), gas.size[0]);
    let (t_mean, pooled) = mean_profile(profiles);
    let line = Line::fit(&pooled, length, width);
    let text = "temperature (mean ± standard error)".into();
    let mut layers = mean_with_band(&pooled.x, &t_mean, colour(0), text).to_vec();
    let ends = [gas.diameter / 2.0, length - gas.diameter / 2.0];
    let text = format!("straight line through the middle {}%", num(100.0 * width));
    layers.push(dashed(
        ends.map(|x| (x, line.at(x))).to_vec(),
        colour(1),
        text,
    ));
    let walls = match hot_high {
        true => [(length, *hot), (0.0, *cold)],
        false => [(0.0, *hot), (length, *cold)],
    };
    let text = Some("wall temperatures".into());
    layers.push(markers(walls.to_vec(), colour(3), text));
    // Density on the same axis, scaled to the temperature's range.
    let n_max = pooled.density.iter().copied().fold(0.0, f64::max);
    if n_max > 0.0 {
        let scaled = pooled.x.iter().zip(&pooled.density);
        let scaled = scaled.map(|(x, n)| (*x, n / n_max * hot)).collect();
        let text = format!("density × {} (its maximum at kT_hot)", num(hot / n_max));
        layers.push(polyline(scaled, colour(2), 1, false, Some(text)));
    }
    let (hot, cold) = (num(*hot), num(*cold));
    let title = format!("Steady profile between walls at kT = {hot} and {cold}, {name}");
    let axes = (title, "x [σ]", "kinetic temperature [kT]");
    let figure = figure(
        &format!("heat_profile_{k}.svg"),
        axes,
        (false, false),
        layers,
    );
    let values = [("name", name), ("runs", rs.outs.len().to_string())];
    show(figures, figure, &fill(named(CAPTIONS, "profile"), &values))
}
