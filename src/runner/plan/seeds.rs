//! Per-run seeds: a pure function of (study seed, the point's swept values,
//! replica), so a run's random stream depends neither on thread count nor on
//! execution order, nor on where its point sits in the sweep: inserting or
//! removing a sweep value leaves every other point's seeds unchanged.

use crate::descriptor::sweep::{Numbers, point_text};

/// SplitMix64's finalizer: a bijective mixer with good avalanche.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

const GOLDEN: u64 = 0x9e37_79b9_7f4a_7c15;

/// The seed of replica `replica` of the sweep point whose `point_key` is
/// given, in a study seeded with `study_seed`. Each input is folded in
/// through a full mix, so neighbouring points and replicas get unrelated seeds.
pub fn run_seed(study_seed: u64, point_key: u64, replica: u32) -> u64 {
    let s = mix(study_seed.wrapping_add(GOLDEN));
    let s = mix(s ^ point_key.wrapping_add(GOLDEN).wrapping_mul(GOLDEN));
    mix(s ^ u64::from(replica).wrapping_add(GOLDEN.rotate_left(17)))
}

/// A sweep point's identity: a hash of its (key path, value) pairs in a
/// canonical text form (`sweep::point_text` with numbers as written),
/// independent of the point's index in the sweep.
pub fn point_key(params: &[(String, toml::Value)]) -> u64 {
    fnv1a(point_text(params, Numbers::AsWritten).as_bytes())
}

/// FNV-1a over bytes: a stable (Rust-version independent) fingerprint hash.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}
