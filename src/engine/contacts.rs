//! Contact times of one particle with a batch of partners. The partners are
//! gathered first, then every contact time is computed at once without a
//! branch: whether a pair approaches is a coin toss that no branch predictor
//! guesses, and branch-free arithmetic over arrays vectorises. The times are
//! those of `collide::contact_time_before`, bit for bit; `Batch::earliest`
//! picks the partner by that function's rules, and passes over a partner
//! whose own event comes first.

use super::neighbours::Image;
use super::vector::Vector;

/// Partners per batch: more than most lists hold, few enough for the stack.
pub const BATCH: usize = 16;
/// Lanes computed together.
const LANES: usize = 4;

/// Separations, relative velocities and contact distances of up to `BATCH`
/// partners, one array per coordinate, and their contact times once computed.
#[derive(Debug, Clone)]
pub struct Batch<const D: usize> {
    /// Each partner's index and image code (the index as 32 bits, half the
    /// bytes to store per partner).
    partner: [(u32, Image); BATCH],
    r: [[f64; BATCH]; D],
    v: [[f64; BATCH]; D],
    sigma: [f64; BATCH],
    /// When each partner's own next event is due.
    due: [f64; BATCH],
    b: [f64; BATCH],
    c: [f64; BATCH],
    dt: [f64; BATCH],
}

impl<const D: usize> Batch<D> {
    pub fn new() -> Self {
        Batch {
            partner: [(0, 0); BATCH],
            r: [[0.0; BATCH]; D],
            v: [[0.0; BATCH]; D],
            sigma: [0.0; BATCH],
            due: [0.0; BATCH],
            b: [0.0; BATCH],
            c: [0.0; BATCH],
            dt: [0.0; BATCH],
        }
    }

    /// Make partner `partner` (index, image) the `m`th of the batch: at
    /// separation `r` (from the particle to it) with relative velocity `v`
    /// (its velocity less the particle's), whose own next event is due at
    /// `due`.
    #[inline(always)]
    pub fn put(
        &mut self,
        m: usize,
        partner: (usize, Image),
        r: &Vector<D>,
        v: &Vector<D>,
        sigma: f64,
        due: f64,
    ) {
        self.partner[m] = (partner.0 as u32, partner.1);
        for k in 0..D {
            self.r[k][m] = r[k];
            self.v[k][m] = v[k];
        }
        self.sigma[m] = sigma;
        self.due[m] = due;
    }

    /// The first `len` partners' times to contact from now: 0 for an
    /// approaching pair that round-off left overlapping, infinity for a pair
    /// that never meets. Lanes go four at a time (one AVX register).
    #[inline(always)]
    fn contact_times(&mut self, len: usize) {
        for group in 0..len.div_ceil(LANES) {
            for m in group * LANES..(group + 1) * LANES {
                // The same operations in the same order as `contact_time_before`.
                let (mut b, mut rr, mut vv) = (0.0, 0.0, 0.0);
                for k in 0..D {
                    b += self.r[k][m] * self.v[k][m];
                    rr += self.r[k][m] * self.r[k][m];
                    vv += self.v[k][m] * self.v[k][m];
                }
                let c = rr - self.sigma[m] * self.sigma[m];
                let disc = b * b - vv * c;
                let t = c / (-b + disc.sqrt());
                let t = if disc > 0.0 { t } else { f64::INFINITY };
                let t = if c <= 0.0 { 0.0 } else { t };
                self.dt[m] = if b < 0.0 { t } else { f64::INFINITY };
                self.b[m] = b;
                self.c[m] = c;
            }
        }
    }

    /// `contact_times` compiled for AVX: the same IEEE operations (Rust never
    /// fuses a multiply and an add on its own), so the same bits, 4 lanes wide.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn contact_times_avx(&mut self, len: usize) {
        self.contact_times(len)
    }

    fn all_contact_times(&mut self, len: usize) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx") {
            // SAFETY: the CPU has just been found to support AVX.
            unsafe { self.contact_times_avx(len) };
            return;
        }
        self.contact_times(len)
    }

    /// Of the first `len` partners put, the first (in order) whose contact comes before
    /// `*best_t` and before the partner's own next event, lowering `*best_t`
    /// as it goes. A partner whose own event comes first is passed over: that
    /// event will change it (or re-predict it) and it will then look for this
    /// particle itself, so a pair's contact is always scheduled on one side
    /// or the other in time, and no prediction waits on a partner already
    /// due to change (a stale event). Times are those of
    /// `contact_time_before(r, v, sigma, *best_t - now)`: that function also
    /// turns down a partner whose time it can bound below by the limit
    /// without computing it (c >= 2|b| limit), which decides differently only
    /// when round-off puts the time within an ulp of the limit, so the same
    /// test is applied here to the rare winners.
    #[inline(always)]
    pub fn earliest(&mut self, len: usize, now: f64, best_t: &mut f64) -> Option<(usize, Image)> {
        self.all_contact_times(len);
        // Which partners could win, without a branch per partner (whether one
        // comes before its own event is as unpredictable as whether it
        // approaches); `*best_t` only falls, so no other one can.
        let mut hopeful = 0u32;
        for m in 0..len {
            let t = now + self.dt[m];
            self.dt[m] = t;
            hopeful |= u32::from(t < *best_t && t < self.due[m]) << m;
        }
        let mut found = None;
        while hopeful != 0 {
            let m = hopeful.trailing_zeros() as usize;
            hopeful &= hopeful - 1;
            let t = self.dt[m];
            if t < *best_t {
                let (b, c) = (self.b[m], self.c[m]);
                if c > 0.0 && c >= -2.0 * b * (*best_t - now) {
                    continue;
                }
                *best_t = t;
                let (j, image) = self.partner[m];
                found = Some((j as usize, image));
            }
        }
        found
    }
}
