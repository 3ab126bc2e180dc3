//! Across the sweep: where the adiabatic theory holds, in terms of the
//! piston's mass over the gases' and its speed over theirs; how the
//! relaxation time grows with M; each result with its cost.

use super::piston_estimators::decay_bound;
use super::summary::Stats;
use crate::report::chart::{ChartSpec, Layer, Paint, render};
use crate::report::format::{count, num, pm};
use crate::report::plots::colour;
use crate::study::output::RunOutput;
use crate::study::plan_types::RunSpec;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

const MASS_KEY: &str = "scene.piston.mass";

/// One sweep point's runs, summarised.
struct Point {
    id: u64,
    /// Swept parameters other than the piston mass ("per_side=5, energy=20").
    group: String,
    mass: f64,
    runs: usize,
    duration: f64,
    sample_every: f64,
    stats: BTreeMap<&'static str, Stats>,
    equipartition: f64,
    seconds: f64,
    collisions: u64,
}

const RESULTS: &[&str] = &[
    "frequency_ratio",
    "frequency_ratio_inertia",
    "frequency_ratio_isothermal",
    "mass_over_gas",
    "speed_ratio",
    "relaxation_time",
    "excess_left",
    "piston_share",
    "frequency",
    "frequency_periods",
];

fn points(runs: &[(RunSpec, RunOutput)]) -> Vec<Point> {
    let mut by_id: BTreeMap<u64, Vec<&(RunSpec, RunOutput)>> = BTreeMap::new();
    for r in runs {
        by_id.entry(r.0.point_id).or_default().push(r);
    }
    by_id
        .into_iter()
        .map(|(id, rs)| {
            let spec = &rs[0].0;
            let group: Vec<String> = spec
                .params
                .iter()
                .filter(|(k, _)| k != MASS_KEY)
                .map(|(k, v)| format!("{}={v}", k.rsplit('.').next().unwrap_or(k)))
                .collect();
            let stats = RESULTS
                .iter()
                .map(|&name| {
                    let v: Vec<f64> = rs
                        .iter()
                        .filter_map(|r| r.1.scalar(name))
                        .filter(|v| v.is_finite())
                        .collect();
                    (name, Stats::of(&v))
                })
                .collect();
            Point {
                id,
                group: group.join(", "),
                mass: rs[0].1.scalar("mass_ratio").unwrap_or(f64::NAN),
                runs: rs.len(),
                duration: spec.descriptor.run.duration.unwrap_or(f64::NAN),
                sample_every: spec.descriptor.run.sample_every.unwrap_or(f64::NAN),
                stats,
                equipartition: super::piston::theory(&spec.descriptor, "piston_share")
                    .unwrap_or(f64::NAN),
                seconds: rs.iter().map(|r| r.1.wall_seconds).sum(),
                collisions: rs.iter().map(|r| r.1.collisions).sum(),
            }
        })
        .collect()
}

impl Point {
    fn stat(&self, name: &str) -> Stats {
        self.stats.get(name).copied().unwrap_or(Stats::of(&[]))
    }

    /// Every run reached 1/e of its excess.
    fn relaxed(&self) -> bool {
        self.stat("relaxation_time").n as usize == self.runs
    }

    /// Lower bound on the mean relaxation time of a point whose runs did not
    /// all reach 1/e: the mean of min(tau, T) over its runs (runs that did not
    /// reach it within T took longer), or, if larger, the bound from what is
    /// left of the excess (at 2 standard errors above the mean, so it errs low).
    fn tau_bound(&self) -> f64 {
        let tau = self.stat("relaxation_time");
        let reached = if tau.n > 0 {
            tau.mean * tau.n as f64
        } else {
            0.0
        };
        let censored =
            (reached + (self.runs - tau.n as usize) as f64 * self.duration) / self.runs as f64;
        let left = self.stat("excess_left");
        let from_left = decay_bound(self.duration, left.mean + 2.0 * left.stderr.max(0.0));
        if from_left.is_finite() {
            censored.max(from_left)
        } else {
            censored
        }
    }
}

/// How a frequency ratio compares with 1: holds (within 1% with two
/// standard errors to spare), small deviation (significant, below 5%),
/// breaks down (significant, above 5%), or too uncertain to tell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Verdict {
    Holds,
    Small,
    Breaks,
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
        Verdict::Unclear => "error too large".into(),
    }
}

/// The regime summary, table and figures.
pub fn regimes(runs: &[(RunSpec, RunOutput)], out_dir: &Path) -> anyhow::Result<String> {
    let points = points(runs);
    let mut md = String::from("\n### Where the adiabatic theory holds\n\n");
    md.push_str(&boundaries(&points));
    let name = frequency_figure(&points, out_dir)?;
    let _ = writeln!(
        md,
        "![Measured frequency over the nonlinear adiabatic prediction against the piston's mass over the gases' mass (mean ± standard error per sweep point); the curve is the gases'-inertia correction sqrt(M/(M + M_gas/3)) for small oscillations.]({name})\n"
    );
    md.push_str(&resolution(&points));
    md.push_str(&table(&points));
    md.push_str("\n### How the piston relaxes, and how a very heavy one ever could\n\n");
    md.push_str(&relaxation(&points, out_dir)?);
    Ok(md)
}

/// Where the theory holds and breaks down, in terms of M/M_gas and the speed ratio.
fn boundaries(points: &[Point]) -> String {
    let mut md = String::new();
    for (result, what) in [
        (
            "frequency_ratio",
            "The adiabatic frequency (piston alone as the inertia)",
        ),
        (
            "frequency_ratio_inertia",
            "With a third of the gases' mass added to the piston's, the adiabatic frequency",
        ),
    ] {
        let judged: Vec<(f64, f64, Verdict)> = points
            .iter()
            .map(|p| {
                (
                    p.stat("mass_over_gas").mean,
                    p.stat("speed_ratio").mean,
                    verdict(&p.stat(result)),
                )
            })
            .filter(|(mu, _, _)| mu.is_finite())
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
                    .all(|j| j.2 == Verdict::Holds)
            })
            .fold(f64::INFINITY, f64::min);
        let breaks_to = judged
            .iter()
            .map(|j| j.0)
            .filter(|&mu| {
                judged
                    .iter()
                    .filter(|j| j.0 <= mu)
                    .all(|j| j.2 == Verdict::Breaks)
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let fastest_holding = judged
            .iter()
            .filter(|j| j.2 == Verdict::Holds)
            .map(|j| j.1)
            .fold(f64::NEG_INFINITY, f64::max);
        let count_of = |v: Verdict| judged.iter().filter(|j| j.2 == v).count();
        let _ = write!(
            md,
            "- {what} holds within 1% (two standard errors to spare) at {} of {} points",
            count_of(Verdict::Holds),
            judged.len()
        );
        if holds_from.is_finite() {
            let _ = write!(md, ", at every point with M/M_gas ≥ {}", num(holds_from));
        }
        if fastest_holding.is_finite() {
            let _ = write!(
                md,
                " (piston speed up to {} of the gases' thermal speed)",
                num(fastest_holding)
            );
        }
        let _ = write!(
            md,
            "; small deviations (< 5%) at {}; breaks down (> 5%) at {}",
            count_of(Verdict::Small),
            count_of(Verdict::Breaks)
        );
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
         starting energy and falls as 1/sqrt(M).\n\n",
    );
    md
}

/// How well the sampling resolves the frequency at the worst point: linear
/// interpolation between samples dt apart places a crossing within
/// (omega dt)^2 / (8 omega), so K periods give omega to (omega dt)^2/(8 pi K)
/// relative (the bound `piston_estimators` tests).
fn resolution(points: &[Point]) -> String {
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

fn table(points: &[Point]) -> String {
    let mut md = String::from(
        "Per sweep point (mean ± standard error over the runs that gave a value, n of N): the frequency over \
         each prediction, the verdict for the plain adiabatic one, the relaxation time (or a lower bound where \
         the runs ended first), the piston's late share of the kinetic energy against 1/N_free, and the cost \
         (CPU seconds and collisions of all the point's runs).\n\n\
         | point | parameters | M/M_gas | v_piston/v_gas | ω/ω_adiabatic (n) | ω/ω_ad+inertia | ω/ω_isothermal | adiabatic | τ relax (n) | excess left | piston share / 1/N_free | CPU s | collisions |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for p in points {
        let s = |name: &str| p.stat(name);
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
        let share = s("piston_share");
        let _ = writeln!(
            md,
            "| {} | M={}, {} | {} | {} | {} ({}/{}) | {} | {} | {} | {} | {} | {} / {} | {:.2} | {} |",
            p.id,
            num(p.mass),
            p.group,
            num(s("mass_over_gas").mean),
            num(s("speed_ratio").mean),
            pm(f.mean, f.stderr),
            f.n,
            p.runs,
            pm(
                s("frequency_ratio_inertia").mean,
                s("frequency_ratio_inertia").stderr
            ),
            pm(
                s("frequency_ratio_isothermal").mean,
                s("frequency_ratio_isothermal").stderr
            ),
            verdict_text(&f),
            relax,
            pm(s("excess_left").mean, s("excess_left").stderr),
            pm(share.mean, share.stderr),
            num(p.equipartition),
            p.seconds,
            count(p.collisions),
        );
    }
    md
}

/// Groups of points (same parameters but the mass), in first-seen order.
fn groups(points: &[Point]) -> Vec<(String, Vec<&Point>)> {
    let mut out: Vec<(String, Vec<&Point>)> = Vec::new();
    for p in points {
        match out.iter_mut().find(|g| g.0 == p.group) {
            Some(g) => g.1.push(p),
            None => out.push((p.group.clone(), vec![p])),
        }
    }
    out
}

fn frequency_figure(points: &[Point], out_dir: &Path) -> anyhow::Result<String> {
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
    let name = "piston_frequency_ratio.svg".to_string();
    let chart = ChartSpec {
        title: "Measured over adiabatic frequency".into(),
        x_label: "piston mass / gas mass, M/M_gas".into(),
        y_label: "ω / ω_adiabatic".into(),
        x_log: true,
        layers,
        ..Default::default()
    };
    crate::study::store::write_atomic(&out_dir.join(&name), render(&chart).as_bytes())?;
    Ok(name)
}

/// Weighted least-squares line through (x, y ± e): slope, its standard
/// error (scaled up by sqrt(chi^2/dof) when the scatter exceeds the error
/// bars), and chi^2/dof.
fn fit_line(points: &[(f64, f64, f64)]) -> Option<(f64, f64, f64, f64)> {
    if points.len() < 3 {
        return None;
    }
    let (mut s, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for &(x, y, e) in points {
        let w = 1.0 / (e * e);
        s += w;
        sx += w * x;
        sy += w * y;
        sxx += w * x * x;
        sxy += w * x * y;
    }
    let det = s * sxx - sx * sx;
    if det.is_nan() || det <= 0.0 {
        return None;
    }
    let slope = (s * sxy - sx * sy) / det;
    let intercept = (sxx * sy - sx * sxy) / det;
    let chi2: f64 = points
        .iter()
        .map(|&(x, y, e)| ((y - intercept - slope * x) / e).powi(2))
        .sum();
    let dof = (points.len() - 2) as f64;
    let se = (s / det).sqrt() * (chi2 / dof).max(1.0).sqrt();
    Some((slope, se, intercept, chi2 / dof))
}

fn relaxation(points: &[Point], out_dir: &Path) -> anyhow::Result<String> {
    let mut md = String::new();
    let mut layers = Vec::new();
    let mut fits = String::new();
    for (i, (group, ps)) in groups(points).into_iter().enumerate() {
        let relaxed: Vec<&&Point> = ps.iter().filter(|p| p.relaxed()).collect();
        let logs: Vec<(f64, f64, f64)> = relaxed
            .iter()
            .map(|p| {
                let s = p.stat("relaxation_time");
                (p.mass.ln(), s.mean.ln(), s.stderr / s.mean)
            })
            .filter(|(_, y, e)| y.is_finite() && *e > 0.0)
            .collect();
        layers.push(Layer::ErrorBars {
            bars: relaxed
                .iter()
                .map(|p| {
                    let s = p.stat("relaxation_time");
                    (
                        p.mass,
                        (s.mean - s.stderr).max(s.mean / 10.0),
                        s.mean,
                        s.mean + s.stderr,
                    )
                })
                .collect(),
            paint: colour(i),
        });
        layers.push(Layer::Markers {
            points: relaxed
                .iter()
                .map(|p| (p.mass, p.stat("relaxation_time").mean))
                .collect(),
            paint: colour(i),
            label: Some(group.clone()),
        });
        // Unrelaxed points: lower bounds, drawn faded.
        layers.push(Layer::Markers {
            points: ps
                .iter()
                .filter(|p| !p.relaxed() && p.tau_bound().is_finite())
                .map(|p| (p.mass, p.tau_bound()))
                .collect(),
            paint: colour(i).faded(0.35),
            label: None,
        });
        if let Some((b, se, a, chi2)) = fit_line(&logs) {
            let masses: Vec<f64> = relaxed.iter().map(|p| p.mass).collect();
            let (lo, hi) = (masses[0], masses[masses.len() - 1]);
            layers.push(Layer::Line {
                points: vec![(lo, (a + b * lo.ln()).exp()), (hi, (a + b * hi.ln()).exp())],
                paint: colour(i),
                width: 1,
                dashed: true,
                label: None,
            });
            let _ = writeln!(
                fits,
                "| {group} | {}–{} | {} | {} | {} | {:.1} | {} |",
                num(lo),
                num(hi),
                logs.len(),
                pm(b, se),
                num(chi2),
                relaxed.iter().map(|p| p.seconds).sum::<f64>(),
                count(relaxed.iter().map(|p| p.collisions).sum()),
            );
        }
    }
    let name = "piston_relaxation_time.svg".to_string();
    let chart = ChartSpec {
        title: "Time for the piston to give away 63% of its excess energy".into(),
        x_label: "piston mass M [m]".into(),
        y_label: "relaxation time τ".into(),
        x_log: true,
        y_log: true,
        layers,
    };
    crate::study::store::write_atomic(&out_dir.join(&name), render(&chart).as_bytes())?;
    md.push_str(
        "A heavy piston moves slowly, so each gas follows its adiabat: every particle bouncing between a wall \
         and the piston keeps its action v·X, and the energy the piston puts into a gas while compressing it \
         comes back while the gas expands. Only the departures from that reversible picture dissipate: \
         particles that meet the piston at different phases of its swing, and collisions inside each gas \
         that share the energy out. A heavier piston is slower next to the gas particles (its speed falls as \
         1/sqrt(M)) and departs less from the adiabat, so its relaxation time grows steeply with M: a very \
         heavy piston loses its energy only through these ever smaller non-adiabatic effects, and in practice \
         keeps it for as long as we can watch. Solid markers: every run reached 1/e of its excess (mean ± \
         standard error); faded markers: lower bounds from what was left of the excess when the runs ended; \
         dashed lines: power-law fits.\n\n",
    );
    let _ = writeln!(
        md,
        "![Relaxation time against piston mass, with power-law fits over the points where every run relaxed, and lower bounds (faded) where the runs ended first.]({name})\n"
    );
    if fits.is_empty() {
        md.push_str("Too few relaxed points (three needed per group) to fit a power law.\n\n");
    } else {
        let _ = write!(
            md,
            "Power law τ ∝ M^b fitted (weighted least squares in log–log, error scaled by sqrt(χ²/dof) where \
             the points scatter more than their error bars) over the points where every run relaxed:\n\n\
             | group | M from–to | points | exponent b | χ²/dof | CPU s | collisions |\n|---|---|---|---|---|---|---|\n{fits}\n"
        );
    }
    let heaviest: Vec<&Point> = points.iter().filter(|p| !p.relaxed()).collect();
    if !heaviest.is_empty() {
        let worst = heaviest
            .iter()
            .max_by(|a, b| a.mass.total_cmp(&b.mass))
            .map(|p| {
                let left = p.stat("excess_left");
                format!(
                    "at M = {} ({}) the piston still holds {} of its starting excess after {} time units, so τ > {}",
                    num(p.mass),
                    p.group,
                    pm(left.mean, left.stderr),
                    num(p.duration),
                    num(p.tau_bound())
                )
            })
            .unwrap_or_default();
        let _ = writeln!(
            md,
            "{} of {} points did not relax within their runs; {worst}.\n",
            heaviest.len(),
            points.len()
        );
    }
    Ok(md)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_fit_recovers_a_power_law() {
        let pts: Vec<(f64, f64, f64)> = [10.0f64, 100.0, 1000.0]
            .iter()
            .map(|m| (m.ln(), (3.0 * m.powf(1.5)).ln(), 0.1))
            .collect();
        let (b, se, a, chi2) = fit_line(&pts).expect("fits");
        assert!((b - 1.5).abs() < 1e-12 && (a - 3f64.ln()).abs() < 1e-12);
        assert!(chi2 < 1e-20);
        // Error of the slope from the error bars alone: 0.1 / sqrt(sum (x - xbar)^2).
        let spread = 2.0 * (10f64.ln()).powi(2);
        assert!((se - 0.1 / spread.sqrt()).abs() < 1e-12);
    }

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
        assert_eq!(verdict(&s(0.98, 0.02)), Verdict::Unclear);
    }
}
