//! The `wall_heat` observable on the real engine: a hard wall exchanges no
//! energy, and a hot thermal wall heats a cold gas.

use bonkers::descriptor::load::parse;
use bonkers::runner::plan::plan;
use bonkers::stats::summary::Stats;

const COLD_GAS_HOT_WALL: &str = r#"
[study]
name = "heat"
replicas = 8
seed = 3

[scene]
dimension = 2
box = [12.0, 12.0]
boundary = ["walls", "walls"]
species = [{ name = "disk", count = 30 }]
velocities = { kind = "maxwell", temperature = 0.2 }
thermal_walls = [{ axis = 0, side = "low", temperature = 5.0 }]

[run]
duration = 20.0

[observe]
scalars = ["wall_heat"]
"#;

#[test]
fn a_hot_wall_heats_a_cold_gas_and_hard_walls_do_not() {
    let runs = plan(&parse("heat.toml", COLD_GAS_HOT_WALL).unwrap()).unwrap();
    let outputs: Vec<_> = runs
        .iter()
        .map(|r| bonkers::runner::execute::simulate::run(r).unwrap())
        .collect();
    for o in &outputs {
        // Elastic walls: exactly no energy, every hit.
        for hard in [
            "heat_in.axis0.high",
            "heat_in.axis1.low",
            "heat_in.axis1.high",
        ] {
            assert_eq!(o.scalar(hard), Some(0.0), "{hard}");
        }
    }
    let hot: Vec<f64> = outputs
        .iter()
        .map(|o| o.scalar("heat_in.axis0.low").unwrap())
        .collect();
    let s = Stats::of(&hot);
    assert_eq!(s.n, 8);
    assert!(
        s.mean > 4.0 * s.stderr,
        "heat from the wall at kT = 5 into a gas at kT = 0.2: {} +- {}",
        s.mean,
        s.stderr
    );
}
