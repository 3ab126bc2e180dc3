//! What this machine's memory allows an engine that has outgrown its caches.
//!
//! `cargo bench --bench memory` (about ten seconds). A 256 MiB buffer (the
//! size of the 10^6-sphere state, far beyond any L3 here) is laid out as one
//! random cycle through its 64-byte lines, and k walkers follow it at once,
//! each from its own start. With k = 1 every line waits for the one before
//! (the latency of a miss to memory, address translation included); with
//! many, the misses overlap up to what the core can keep in flight, and the
//! time per line levels off at the most this core can fetch. Set beside the
//! engine's lines per collision (`docs/performance.md`), it bounds what the
//! largest systems can cost.

use std::hint::black_box;
use std::time::Instant;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

const LINES: usize = 1 << 22; // 256 MiB of 64-byte lines
const VISITS: usize = 1 << 23; // lines read per measurement

#[repr(C, align(64))]
#[derive(Clone, Copy)]
struct Line {
    next: u32,
    _pad: [u32; 15],
}

fn main() {
    // Sattolo's shuffle: a random permutation that is one single cycle.
    let mut lines = vec![
        Line {
            next: 0,
            _pad: [0; 15]
        };
        LINES
    ];
    for (i, l) in lines.iter_mut().enumerate() {
        l.next = i as u32;
    }
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    for i in (1..LINES).rev() {
        let j = rng.random_range(0..i);
        let (a, b) = (lines[i].next, lines[j].next);
        lines[i].next = b;
        lines[j].next = a;
    }
    println!("| lines in flight | ns per line | ns per step (every walker one line) |");
    println!("|---|---|---|");
    let mut cycle = Vec::with_capacity(LINES);
    let mut p = 0u32;
    for _ in 0..LINES {
        cycle.push(p);
        p = lines[p as usize].next;
    }
    for k in [1usize, 2, 4, 8, 12, 16, 24, 32] {
        // Starts spread along the cycle, so that walkers never meet.
        let mut at: Vec<u32> = (0..k).map(|w| cycle[w * (LINES / k)]).collect();
        let steps = VISITS / k;
        let start = Instant::now();
        for _ in 0..steps {
            for a in at.iter_mut() {
                *a = lines[*a as usize].next;
            }
        }
        let ns = start.elapsed().as_secs_f64() * 1e9;
        black_box(&at);
        println!(
            "| {k} | {:.1} | {:.1} |",
            ns / (steps * k) as f64,
            ns / steps as f64
        );
    }
}
