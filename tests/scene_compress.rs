//! Lubachevsky–Stillinger compression: dense, overlap-free starts.

use bonkers::engine::{Disks, Spheres, Stop};
use bonkers::scene::spec::SceneSpec;
use bonkers::scene::{Built, build, resolve};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn built<const D: usize>(text: &str, seed: u64) -> Result<Built<D>, String> {
    let spec: SceneSpec = toml::from_str(text).expect("scene TOML");
    build::<D>(&resolve(&spec)?, &mut ChaCha8Rng::seed_from_u64(seed))
}

/// Box edge for n unit-diameter particles at packing fraction phi.
fn edge(d: usize, n: usize, phi: f64) -> f64 {
    let v = if d == 2 {
        std::f64::consts::PI / 4.0
    } else {
        std::f64::consts::PI / 6.0
    };
    (n as f64 * v / phi).powf(1.0 / d as f64)
}

#[test]
fn explore() {
    for (d, n, phi, boundary, rate) in [
        (2, 400, 0.88, "periodic", 0.005),
        (2, 401, 0.88, "periodic", 0.005),
        (2, 402, 0.88, "periodic", 0.005),
        (2, 400, 0.89, "periodic", 0.001),
        (3, 250, 0.64, "periodic", 0.005),
        (3, 251, 0.64, "periodic", 0.005),
    ] {
        let l = edge(d, n, phi);
        let text = format!(
            "box = {:?}\nboundary = {:?}\nspecies = [{{ name = \"a\", count = {n} }}]\nplacement = {{ kind = \"compress\", growth_rate = {rate} }}\n",
            vec![l; d],
            vec![boundary; d]
        );
        let t = std::time::Instant::now();
        let (prep, overlap) = if d == 2 {
            match built::<2>(&text, 1) {
                Ok(b) => {
                    let p = b.prepared;
                    let sim = Disks::new(b.particles, b.sim_box, (), 1).unwrap();
                    (Ok(p), sim.max_overlap())
                }
                Err(e) => (Err(e), 0.0),
            }
        } else {
            match built::<3>(&text, 1) {
                Ok(b) => {
                    let p = b.prepared;
                    let sim = Spheres::new(b.particles, b.sim_box, (), 1).unwrap();
                    (Ok(p), sim.max_overlap())
                }
                Err(e) => (Err(e), 0.0),
            }
        };
        println!(
            "{d}D n={n} phi={phi} {boundary} rate={rate}: {:?} overlap {overlap:e} in {:?}",
            prep,
            t.elapsed()
        );
    }
    let _ = Stop::Time(0.0);
}
