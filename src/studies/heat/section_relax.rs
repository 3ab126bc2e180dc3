//! The relaxation part of the heat section: per point the mean temperature
//! against time beside the well-mixed model and the collisionless gas, and
//! a row of times, initial rates and the settled temperature; then the
//! relaxation time over the model's against the Knudsen number.

use super::section::{CAPTIONS, Runs, bar, dashed, figure, label, measured, with_z};
use super::{Gas, model, passage};
use crate::model::chart::colour;
use crate::model::report::Figure;
use crate::stats::fill::fill;
use crate::stats::format::{count, num};
use crate::stats::named::named;
use crate::stats::summary::Stats;
use crate::stats::table::table_row;
use crate::studies::curves::{mean_with_band, show};
use crate::studies::parts::stat_pm;

const TEXT: &str = include_str!("relax.md");

/// The relaxation charts show this many well-mixed relaxation times.
const SHOWN: f64 = 5.0;

/// `window`: the `initial_window` option.
pub fn part(window: f64, points: &[(Gas, f64, Runs)], figures: &mut Vec<Figure>) -> String {
    let (mut rows, mut pictures, mut ratio_bars) = (String::new(), String::new(), Vec::new());
    for (k, (gas, wall, rs)) in points.iter().enumerate() {
        let name = label(rs, gas);
        // T = 2K / (d N), the same for every run of the point.
        let (t, energy) = rs.mean_curve("kinetic_energy");
        let per_energy = 2.0 / (gas.dimension as f64 * gas.particles);
        let mean: Vec<Stats> = energy.iter().map(|s| s.scaled(per_energy)).collect();
        let start = mean.first().map_or(f64::NAN, |s| s.mean);
        let m = model(gas, *wall, start);
        let curve: Vec<f64> = mean.iter().map(|s| s.mean).collect();
        let ratio = rs.stat("relaxation_ratio");
        let half_d = gas.dimension as f64 / 2.0;
        let free = gas.free(*wall, start, t.last().copied().unwrap_or(0.0));
        let kn = gas.knudsen();
        if ratio.mean.is_finite() && kn.is_finite() {
            ratio_bars.push(bar(kn, &ratio));
        }
        let tau_free = free.as_ref().map(|f| f.relaxation_time(half_d * wall));
        rows.push_str(&table_row(&[
            name.clone(),
            num(kn),
            rs.outs.len().to_string(),
            stat_pm(rs, "relaxation_time"),
            num(passage(&t, &curve, *wall, (-1f64).exp())),
            num(m.relaxation_time()),
            stat_pm(rs, "relaxation_ratio"),
            num(tau_free.unwrap_or(f64::NAN)),
            stat_pm(rs, "relaxation_ratio_free"),
            with_z(&rs.stat("initial_rate_ratio"), 1.0),
            with_z(&rs.stat("late_temperature"), *wall),
            num(rs.cpu()),
            count(rs.collisions()),
        ]));
        let shown = (t.iter())
            .take_while(|&&x| x <= SHOWN * m.relaxation_time())
            .count()
            .max(2)
            .min(t.len());
        let (t, mean) = (&t[..shown], &mean[..shown]);
        let text = "measured (mean ± standard error)".into();
        let mut layers = mean_with_band(t, mean, colour(0), text).to_vec();
        let model_curve = t.iter().map(|&x| (x, m.temperature(x))).collect();
        layers.push(dashed(model_curve, colour(1), "well-mixed model".into()));
        if let Some(f) = &free {
            let free_curve = t.iter().map(|&x| (x, f.energy_at(x) / half_d)).collect();
            let text = "collisionless (exact for points)".into();
            layers.push(dashed(free_curve, colour(2), text));
        }
        let title = format!(
            "Temperature relaxing to walls at kT = {}, {name}",
            num(*wall)
        );
        let axes = (
            title,
            "time t [σ √(m/kT)]",
            "kinetic temperature 2K/(dN) [kT]",
        );
        let figure = figure(
            &format!("heat_relaxation_{k}.svg"),
            axes,
            (false, false),
            layers,
        );
        let values = [("name", name), ("runs", rs.outs.len().to_string())];
        pictures.push_str(&show(
            figures,
            figure,
            &fill(named(CAPTIONS, "relaxation"), &values),
        ));
    }
    let mut ratio_figure = String::new();
    if !ratio_bars.is_empty() {
        let xs = ratio_bars.iter().map(|b| b.0);
        let ends = [
            (xs.clone().fold(f64::INFINITY, f64::min), 1.0),
            (xs.fold(0.0, f64::max), 1.0),
        ];
        let mut layers =
            measured(ratio_bars, colour(0), "measured (mean ± standard error)").to_vec();
        layers.push(dashed(ends.to_vec(), colour(1), "well-mixed model".into()));
        let title = "Relaxation time over the well-mixed model's, against Kn".into();
        let axes = (title, "Knudsen number λ/L", "τ / τ well-mixed");
        let figure = figure("heat_relaxation_ratio.svg", axes, (true, false), layers);
        ratio_figure = show(figures, figure, named(CAPTIONS, "ratio"));
    }
    fill(
        TEXT,
        &[
            ("window", num(window)),
            ("pictures", pictures),
            ("rows", rows),
            ("ratio_figure", ratio_figure),
        ],
    )
}
