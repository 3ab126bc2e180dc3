//! Across the sweep: where the adiabatic theory holds, in terms of the
//! piston's mass over the gases' and its speed over theirs (and in 2D the
//! gases' collisions per radian of the swing); how the relaxation time grows
//! with M; the long-time share against equipartition; each with its cost.
//! One part per dimension the sweep holds.

use crate::model::chart::colour;
use crate::model::chart::{ChartSpec, Layer, Paint};
use crate::model::report::Figure;
use crate::model::run_output::RunOutput;
use crate::model::run_spec::RunSpec;
use crate::stats::format::{count, num, pm};
use crate::stats::summary::Stats;
use crate::studies::piston::points::{Point, by_dimension, groups, points};
use crate::studies::piston::relaxation::relaxation;
use std::fmt::Write;

/// How a frequency ratio compares with 1: holds (within 1% with two
/// standard errors to spare), small deviation (significant, below 5%),
/// breaks down (significant, above 5%), agrees within an error bar that
/// would show a 5% deviation, or too uncertain to tell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Verdict {
    Holds,
    Small,
    Breaks,
    Agrees,
    Unclear,
}

fn verdict(s: &Stats) -> Verdict {
    let gap = (s.mean - 1.0).abs();
    if !s.mean.is_finite() || !s.stderr.is_finite() {
        Verdict::Unclear
    } else if gap + 2.0 * s.stderr < 0.01 {
        Verdict::Holds
    } else if gap > 3.0 * s.stderr && gap < 0.05 {
        Verdict::Small
    } else if gap > 3.0 * s.stderr {
        Verdict::Breaks
    } else if gap + 3.0 * s.stderr < 0.05 {
        Verdict::Agrees
    } else {
        Verdict::Unclear
    }
}

fn verdict_text(s: &Stats) -> String {
    let gap = 100.0 * (s.mean - 1.0);
    match verdict(s) {
        Verdict::Holds => format!("holds ({gap:+.2}%)"),
        Verdict::Small => format!("small deviation ({gap:+.1}%)"),
        Verdict::Breaks => format!("breaks down ({gap:+.0}%)"),
        Verdict::Agrees => format!("agrees (±{:.1}%)", 100.0 * s.stderr),
        Verdict::Unclear => "error too large".into(),
    }
}

/// The regime summary, tables and figures, one part per dimension.
pub fn regimes(runs: &[(RunSpec, RunOutput)], figures: &mut Vec<Figure>) -> anyhow::Result<String> {
    let all = points(runs);
    let mut md = String::new();
    for (dimension, points) in by_dimension(&all) {
        let _ = writeln!(
            md,
            "\n### {}: where the adiabatic theory holds\n",
            heading(dimension)
        );
        md.push_str(&boundaries(&points, dimension));
        let name = frequency_figure(&points, dimension, figures)?;
        let _ = writeln!(
            md,
            "![{dimension}D: measured frequency over the nonlinear adiabatic prediction against the piston's mass over the gases' mass (mean ± standard error per sweep point); the curve is the gases'-inertia correction sqrt(M/(M + M_gas/3)) for small oscillations.]({name})\n"
        );
        md.push_str(&resolution(&points));
        md.push_str(&table(&points, dimension));
        let _ = writeln!(md, "\n### {}: how the piston relaxes\n", heading(dimension));
        md.push_str(&relaxation(&points, dimension, figures)?);
        let _ = writeln!(md, "\n### {}: the long-time share\n", heading(dimension));
        md.push_str(&equipartition(&points));
    }
    Ok(md)
}

fn heading(dimension: usize) -> &'static str {
    match dimension {
        1 => "Rods (1D)",
        2 => "Disks beside a wall (2D)",
        _ => "Spheres beside a wall (3D)",
    }
}

/// Where the theory holds and breaks down, in terms of M/M_gas, the speed
/// ratio and (across x) omega tau.
fn boundaries(points: &[&Point], dimension: usize) -> String {
    let mut md = String::new();
    let mut judged_results = vec![
        (
            "frequency_ratio",
            "The adiabatic frequency (piston alone as the inertia)",
        ),
        (
            "frequency_ratio_inertia",
            "With a third of the gases' mass added to the piston's, the adiabatic frequency",
        ),
    ];
    if dimension > 1 {
        judged_results.push((
            "frequency_ratio_exchange",
            "With the gases' inertia and their lag in sharing the compression (exchange theory), the frequency",
        ));
    }
    for (result, what) in judged_results {
        let judged: Vec<(f64, f64, f64, Verdict)> = points
            .iter()
            .map(|p| {
                (
                    p.stat("mass_over_gas").mean,
                    p.stat("speed_ratio").mean,
                    p.stat("omega_tau").mean,
                    verdict(&p.stat(result)),
                )
            })
            .filter(|(mu, ..)| mu.is_finite())
            .collect();
        // The smallest M/M_gas from which on every point holds, and the
        // largest up to which every point breaks down.
        let holds_from = judged
            .iter()
            .map(|j| j.0)
            .filter(|&mu| {
                judged
                    .iter()
                    .filter(|j| j.0 >= mu)
                    .all(|j| j.3 == Verdict::Holds)
            })
            .fold(f64::INFINITY, f64::min);
        let breaks_to = judged
            .iter()
            .map(|j| j.0)
            .filter(|&mu| {
                judged
                    .iter()
                    .filter(|j| j.0 <= mu)
                    .all(|j| j.3 == Verdict::Breaks)
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let holding = |f: fn(&(f64, f64, f64, Verdict)) -> f64| {
            judged
                .iter()
                .filter(|j| j.3 == Verdict::Holds)
                .map(f)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let count_of = |v: Verdict| judged.iter().filter(|j| j.3 == v).count();
        let _ = write!(
            md,
            "- {what} holds within 1% (two standard errors to spare) at {} of {} points",
            count_of(Verdict::Holds),
            judged.len()
        );
        if holds_from.is_finite() {
            let _ = write!(md, ", at every point with M/M_gas ≥ {}", num(holds_from));
        }
        let fastest = holding(|j| j.1);
        if fastest.is_finite() {
            let _ = write!(
                md,
                " (piston speed up to {} of the gases' thermal speed",
                num(fastest)
            );
            let wt = holding(|j| j.2);
            if dimension > 1 && wt.is_finite() {
                let _ = write!(md, ", ωτ_x up to {}", num(wt));
            }
            md.push(')');
        }
        for (verdict, label) in [
            (
                Verdict::Agrees,
                "agrees within an error bar that would show 5%",
            ),
            (Verdict::Small, "small deviations (< 5%)"),
            (Verdict::Breaks, "breaks down (> 5%)"),
        ] {
            let n = count_of(verdict);
            if n > 0 {
                let _ = write!(
                    md,
                    "; {label} at {n} point{}",
                    if n == 1 { "" } else { "s" }
                );
            }
        }
        if breaks_to.is_finite() {
            let _ = write!(md, ", at every point with M/M_gas ≤ {}", num(breaks_to));
        }
        md.push_str(".\n");
    }
    md.push_str(
        "\nThe physical parameter is M/M_gas, the piston's mass over the gases' (M_gas = both sides): the \
         period over the gas's sound-crossing time X/c is 2π·sqrt(M/M_gas) for a symmetric piston (c² = γkT/m), so a \
         light piston oscillates as fast as the gas can carry the compression across, and the gas's own inertia \
         adds M_gas/3 to the piston's (the frequency falls by about M_gas/(6M)). The speed ratio (peak piston \
         speed over the gases' thermal speed) measures how far from slow the compression is; it grows with the \
         starting energy and falls as 1/sqrt(M).",
    );
    if dimension > 1 {
        md.push_str(
            " Across x there is a second parameter: ωτ_x, the radians the piston swings in the time τ_x the disks \
             take to share heat between x and y (a mean free time). For ωτ_x ≪ 1 the gas compresses as a 2D gas \
             (γ = 2); for ωτ_x ≫ 1 as a collisionless one, each disk keeping its x-action like a rod in 1D (γ = 3, \
             a frequency sqrt(3/2) = 1.22 times higher); in between it lags and dissipates. The exchange theory \
             puts the two together with the gases' inertia.",
        );
    }
    md.push_str("\n\n");
    md
}

/// How well the sampling resolves the frequency at the worst point: linear
/// interpolation between samples dt apart places a crossing within
/// (omega dt)^2 / (8 omega), so K periods give omega to (omega dt)^2/(8 pi K)
/// relative (the bound `piston_estimators` tests).
fn resolution(points: &[&Point]) -> String {
    // (samples per period, relative bound, bound over the relative error bar)
    let worst = points
        .iter()
        .map(|p| {
            let omega = p.stat("frequency");
            let periods = p.stat("frequency_periods").mean.max(1.0);
            let step = omega.mean * p.sample_every;
            let bound = step * step / (8.0 * std::f64::consts::PI * periods);
            (
                std::f64::consts::TAU / step,
                bound,
                bound / (omega.stderr / omega.mean),
            )
        })
        .filter(|w| w.0.is_finite())
        .fold((f64::INFINITY, 0.0f64, 0.0f64), |w, v| {
            (w.0.min(v.0), w.1.max(v.1), w.2.max(v.2))
        });
    if worst.0.is_finite() {
        format!(
            "Sampling: at least {:.0} samples per measured period at every point, so interpolating the \
             crossings limits the frequency to {:.1e} relative, at most {:.0}% of a point's standard error.\n\n",
            worst.0,
            worst.1,
            100.0 * worst.2
        )
    } else {
        String::new()
    }
}

fn table(points: &[&Point], dimension: usize) -> String {
    let across = dimension > 1;
    let mut md = String::from(
        "Per sweep point (mean ± standard error over the runs that gave a value, n of N): the frequency over \
         each prediction, the verdict for the plain adiabatic one, the relaxation time (or a lower bound where \
         the runs ended first), the piston's late share of the kinetic energy against 1/N_free, and the cost \
         (CPU seconds and collisions of all the point's runs).",
    );
    if across {
        md.push_str(
            " Across x also ωτ_x, the frequency over the exchange theory's (inertia and lag) and over the \
             collisionless one (γ = 3), and the relaxation time the exchange theory predicts.\n\n\
             | point | parameters | M/M_gas | v_piston/v_gas | ωτ_x | ω/ω_adiabatic (n) | ω/ω_ad+inertia | ω/ω_exchange | ω/ω_γ=3 | ω/ω_isothermal | adiabatic | τ relax (n) | τ exchange | excess left | piston share / 1/N_free | CPU s | collisions |\n\
             |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        );
    } else {
        md.push_str(
            "\n\n| point | parameters | M/M_gas | v_piston/v_gas | ω/ω_adiabatic (n) | ω/ω_ad+inertia | ω/ω_isothermal | adiabatic | τ relax (n) | excess left | piston share / 1/N_free | CPU s | collisions |\n\
             |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        );
    }
    for p in points {
        let s = |name: &str| p.stat(name);
        let both = |name: &str| pm(s(name).mean, s(name).stderr);
        let f = s("frequency_ratio");
        let tau = s("relaxation_time");
        let relax = if p.relaxed() {
            format!("{} ({}/{})", pm(tau.mean, tau.stderr), tau.n, p.runs)
        } else {
            format!(
                "> {} ({}/{} reached 1/e)",
                num(p.tau_bound()),
                tau.n,
                p.runs
            )
        };
        let mut row = format!(
            "| {} | {} | {} | {} |",
            p.id,
            p.label(),
            num(s("mass_over_gas").mean),
            num(s("speed_ratio").mean),
        );
        if across {
            let _ = write!(row, " {} |", num(s("omega_tau").mean));
        }
        let _ = write!(
            row,
            " {} ({}/{}) | {} |",
            pm(f.mean, f.stderr),
            f.n,
            p.runs,
            both("frequency_ratio_inertia")
        );
        if across {
            let _ = write!(
                row,
                " {} | {} |",
                both("frequency_ratio_exchange"),
                both("frequency_ratio_collisionless")
            );
        }
        let _ = write!(
            row,
            " {} | {} | {} |",
            both("frequency_ratio_isothermal"),
            verdict_text(&f),
            relax
        );
        if across {
            let _ = write!(row, " {} |", num(s("relaxation_time_exchange").mean));
        }
        let _ = writeln!(
            row,
            " {} | {} / {} | {:.2} | {} |",
            both("excess_left"),
            both("piston_share"),
            num(p.equipartition),
            p.seconds,
            count(p.collisions),
        );
        md.push_str(&row);
    }
    md
}

fn frequency_figure(
    points: &[&Point],
    dimension: usize,
    figures: &mut Vec<Figure>,
) -> anyhow::Result<String> {
    let mut layers = Vec::new();
    for (i, (group, ps)) in groups(points).into_iter().enumerate() {
        let at = |p: &Point| (p.stat("mass_over_gas").mean, p.stat("frequency_ratio"));
        layers.push(Layer::ErrorBars {
            bars: ps
                .iter()
                .map(|p| {
                    let (mu, s) = at(p);
                    (mu, s.mean - s.stderr, s.mean, s.mean + s.stderr)
                })
                .collect(),
            paint: colour(i),
        });
        layers.push(Layer::Markers {
            points: ps.iter().map(|p| (at(p).0, at(p).1.mean)).collect(),
            paint: colour(i),
            label: Some(group),
        });
    }
    let mus: Vec<f64> = points
        .iter()
        .map(|p| p.stat("mass_over_gas").mean)
        .filter(|m| m.is_finite() && *m > 0.0)
        .collect();
    let (lo, hi) = (
        mus.iter().copied().fold(f64::INFINITY, f64::min),
        mus.iter().copied().fold(0.0, f64::max),
    );
    if hi > lo {
        layers.push(Layer::Line {
            points: (0..=100)
                .map(|k| {
                    let mu = lo * (hi / lo).powf(k as f64 / 100.0);
                    (mu, (mu / (mu + 1.0 / 3.0)).sqrt())
                })
                .collect(),
            paint: Paint::solid((0, 0, 0)),
            width: 1,
            dashed: true,
            label: Some("gas inertia: sqrt(M/(M + M_gas/3))".into()),
        });
    }
    let name = format!("piston_frequency_ratio_{dimension}d.svg");
    let chart = ChartSpec {
        title: format!("{dimension}D: measured over adiabatic frequency"),
        x_label: "piston mass / gas mass, M/M_gas".into(),
        y_label: "ω / ω_adiabatic".into(),
        x_log: true,
        layers,
        ..Default::default()
    };
    figures.push(Figure {
        file: name.to_string(),
        chart,
    });
    Ok(name)
}

/// The piston's late share of the kinetic energy against 1/N_free, at the
/// points whose runs all relaxed within a tenth of the run (so the late
/// half is at equilibrium), with its cost.
fn equipartition(points: &[&Point]) -> String {
    let settled: Vec<&&Point> = points
        .iter()
        .filter(|p| p.relaxed() && p.stat("relaxation_time").mean < 0.1 * p.duration)
        .collect();
    let mut md = format!(
        "The piston moves along x only, so it holds one of the N_free = d N_gas + 1 kinetic degrees of freedom: \
         at equilibrium its mean share of the kinetic energy is 1/N_free, whatever its mass. The late share \
         (averaged over the last half of each run) tests this where the runs relaxed within a tenth of their \
         length: {} of {} points here (elsewhere the table's share measures how far from equilibrium the piston \
         still is).\n\n",
        settled.len(),
        points.len()
    );
    if settled.is_empty() {
        return md;
    }
    md.push_str(
        "| point | parameters | piston share | 1/N_free | share × N_free | z | oscillator share (× N_free) | CPU s |\n|---|---|---|---|---|---|---|---|\n",
    );
    let mut within = 0;
    for p in &settled {
        let share = p.stat("piston_share");
        let z = (share.mean - p.equipartition) / share.stderr;
        within += usize::from(z.abs() <= 4.0);
        let osc = p.stat("oscillator_share");
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {:+.1} | {} | {:.2} |",
            p.id,
            p.label(),
            pm(share.mean, share.stderr),
            num(p.equipartition),
            pm(share.mean / p.equipartition, share.stderr / p.equipartition),
            z,
            pm(osc.mean / p.equipartition, osc.stderr / p.equipartition),
            p.seconds
        );
    }
    let _ = writeln!(
        md,
        "\n{within} of {} agree with 1/N_free within four standard errors. The oscillator share (its kinetic \
         plus adiabatic potential energy, per 1/N_free) is about two degrees of freedom, as for a harmonic \
         oscillator; the summary table sets it beside its microcanonical mean.\n",
        settled.len()
    );
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts() {
        let s = |mean, stderr| Stats {
            n: 8,
            mean,
            std: f64::NAN,
            stderr,
            ci_low: f64::NAN,
            ci_high: f64::NAN,
        };
        assert_eq!(verdict(&s(1.002, 0.001)), Verdict::Holds);
        assert_eq!(verdict(&s(0.98, 0.002)), Verdict::Small);
        assert_eq!(verdict(&s(0.8, 0.01)), Verdict::Breaks);
        assert_eq!(verdict(&s(0.99, 0.01)), Verdict::Agrees);
        assert_eq!(verdict(&s(0.98, 0.02)), Verdict::Unclear);
    }
}
