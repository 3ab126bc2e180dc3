//! The sweep points as the report sees them: what each point's replicas
//! measured, pooled, and how the point was started and equilibrated.

use super::equations;
use super::packing;
use crate::model::scene::Placement;
use crate::stats::ensemble::Runs;
use crate::stats::point_runs::{PointRuns, by_point};
use crate::stats::summary::Stats;

/// Replicas from which their spread alone is the error bar (a standard
/// error good to 18 %, which also covers what a run's blocks cannot see).
/// With fewer, 4 replicas that agree by luck give |z| of 5 or more about 1 %
/// of the time, so the runs' own error is used where it is larger.
pub const TRUSTED_REPLICAS: u64 = 16;

/// One sweep point.
pub struct Point {
    pub dimension: usize,
    pub particles: usize,
    pub eta: f64,
    /// Whether any axis has walls (then Z is the wall pressure's).
    pub walls: bool,
    /// "random", "lattice" or "compressed".
    pub start: &'static str,
    /// Z over the replicas.
    pub z: Stats,
    /// Block-average standard error of the point's mean Z (the replicas'
    /// block errors combined), the mean block length (time) and the
    /// largest ratio of the estimate with blocks twice as long (NaN where
    /// a run had too few blocks to double).
    pub block_stderr: f64,
    pub block_time: f64,
    pub block_doubling: f64,
    /// The runs' own standard error of the point's mean Z, combined like
    /// `block_stderr`, and what it comes from ("blocks" or "wall hits").
    pub run_stderr: f64,
    pub run_basis: &'static str,
    /// Time discarded before recording (the descriptor's `equilibrate`),
    /// the mean time the MSER rule cut after it, and the largest |drift|.
    pub equilibrate: f64,
    pub cut: f64,
    pub drift: f64,
    /// Pair collisions per particle per unit time while measuring, and
    /// per particle while compressing the start (0 for other starts).
    pub collision_rate: f64,
    pub prepare_per_particle: f64,
    /// Z from the walls minus Z from the virial, paired per replica.
    pub wall_minus_virial: Option<Stats>,
    pub z_wall: Option<Stats>,
    pub z_virial: Option<Stats>,
    pub cpu_seconds: f64,
    /// The first replica's pressure series (time, P), as stored.
    pub example: Option<(Vec<f64>, Vec<f64>)>,
}

impl Point {
    /// The point's error bar on Z and where it comes from.
    /// (See `TRUSTED_REPLICAS`.)
    pub fn error(&self) -> (f64, &'static str) {
        let replicas = self.z.stderr;
        let own = self.run_stderr;
        let trusted = self.z.n >= TRUSTED_REPLICAS && replicas.is_finite();
        if trusted || !own.is_finite() || own <= replicas {
            (replicas, "replicas")
        } else {
            (own, self.run_basis)
        }
    }

    /// Rods, and periodic boxes: the points the bulk equations describe.
    pub fn bulk(&self) -> bool {
        self.dimension == 1 || !self.walls
    }

    /// Whether the dimension's reference equation holds at the point's η.
    pub fn reference_holds(&self) -> bool {
        self.eta <= equations::of(self.dimension)[0].holds_below
    }

    /// Z with the point's error bar, as `Stats` for z-scores.
    pub fn z_stats(&self) -> Stats {
        Stats {
            stderr: self.error().0,
            ..self.z
        }
    }
}

/// The sweep's points with a measured Z, in plan order.
pub fn points(runs: &Runs) -> Vec<Point> {
    let mut all = by_point(runs);
    for p in &mut all {
        p.outs
            .retain(|o| o.scalar("Z").is_some_and(|z| !z.is_nan()));
    }
    (all.iter())
        .filter(|p| p.spec.case.is_none() && !p.outs.is_empty())
        .filter_map(point)
        .collect()
}

fn point(p: &PointRuns) -> Option<Point> {
    let d = &p.spec.descriptor;
    let s = packing::described(d)?;
    let runs = p.outs.len();
    // The measured values of a result (a run writes NaN where it could not
    // measure it), and those only if every run measured it.
    let of = |name: &str| -> Vec<f64> {
        (p.outs.iter().filter_map(|o| o.scalar(name)))
            .filter(|v| !v.is_nan())
            .collect()
    };
    let every = |name: &str| Some(of(name)).filter(|v| v.len() == runs);
    let mean = |name: &str| p.stat(name).mean;
    // The runs' standard errors combined into that of their mean.
    let combined = |name: &str| {
        every(name).map_or(f64::NAN, |v| {
            v.iter().map(|s| s * s).sum::<f64>().sqrt() / runs as f64
        })
    };
    let duration = d.run.duration.unwrap_or(f64::NAN);
    let paired: Option<Vec<f64>> = (p.outs.iter())
        .map(|o| Some(o.scalar("Z_wall")? - o.scalar("Z_virial")?).filter(|v| !v.is_nan()))
        .collect();
    let example = p.outs[0].series.iter().find_map(|s| {
        ["wall_pressure", "virial_pressure"]
            .contains(&s.observable.as_str())
            .then(|| (s.t.clone(), s.value.clone()))
    });
    Some(Point {
        dimension: s.dimension,
        particles: s.particles,
        eta: mean("packing_fraction"),
        walls: s.walls,
        start: match s.scene.placement {
            Some(Placement::Compress { .. }) => "compressed",
            Some(Placement::Lattice { .. }) => "lattice",
            _ => "random",
        },
        z: p.stat("Z"),
        block_stderr: combined("Z_block_stderr"),
        run_stderr: combined("Z_run_stderr"),
        run_basis: if s.dimension == 1 && s.walls {
            "wall hits"
        } else {
            "blocks"
        },
        block_time: mean("block_time"),
        block_doubling: every("block_doubling")
            .map_or(f64::NAN, |v| v.iter().copied().fold(0.0, f64::max)),
        equilibrate: d.run.equilibrate,
        cut: mean("equilibration_cut"),
        drift: of("Z_drift").iter().map(|x| x.abs()).fold(0.0, f64::max),
        collision_rate: p.collisions() as f64 / (s.particles as f64 * duration * runs as f64),
        prepare_per_particle: mean("prepare_collisions") / s.particles as f64,
        wall_minus_virial: paired.map(|v| Stats::of(&v)),
        z_wall: every("Z_wall").map(|v| Stats::of(&v)),
        z_virial: every("Z_virial").map(|v| Stats::of(&v)),
        cpu_seconds: p.cpu(),
        example,
    })
}

#[cfg(test)]
pub(super) mod tests {
    use super::Point;
    use crate::stats::summary::Stats;

    /// A point with 8 replicas of mean `z` and standard error `err`.
    pub fn point(d: usize, n: usize, eta: f64, z: f64, err: f64) -> Point {
        Point {
            dimension: d,
            particles: n,
            eta,
            walls: false,
            start: "random",
            z: Stats {
                n: 8,
                mean: z,
                std: err * 8f64.sqrt(),
                stderr: err,
                ..Stats::of(&[])
            },
            block_stderr: err,
            run_stderr: err,
            run_basis: "blocks",
            block_time: 1.0,
            block_doubling: 1.0,
            equilibrate: 0.0,
            cut: 0.0,
            drift: 0.0,
            collision_rate: 1.0,
            prepare_per_particle: 0.0,
            wall_minus_virial: None,
            z_wall: None,
            z_virial: None,
            cpu_seconds: 0.0,
            example: None,
        }
    }

    #[test]
    fn few_replicas_that_agree_by_luck_do_not_set_the_error() {
        // 4 replicas scattering 5x less than their runs' own error: the
        // runs' error is used; more scatter than it: the replicas'.
        let mut p = point(2, 256, 0.3, 2.06, 0.0005);
        p.z.n = 4;
        p.run_stderr = 0.0025;
        assert_eq!(p.error(), (0.0025, "blocks"));
        p.run_stderr = 0.0001;
        assert_eq!(p.error(), (0.0005, "replicas"));
        // From 16 replicas their spread is the error bar whatever the runs say.
        p.z.n = 16;
        p.run_stderr = 0.0025;
        assert_eq!(p.error(), (0.0005, "replicas"));
        // Without a run error (a scalar-only run), the replicas'.
        p.z.n = 4;
        p.run_stderr = f64::NAN;
        assert_eq!(p.error(), (0.0005, "replicas"));
    }
}
