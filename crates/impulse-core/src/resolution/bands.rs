//! Resolution on several threads: a large contact list resolved band by band,
//! so that contacts which share no disc run side by side.
//!
//! Gauss–Seidel resolution is sequential by nature: each contact sees the
//! velocities and positions the contacts before it left. What can run side by
//! side is contacts that share no disc. The world's height is cut into
//! [`BANDS`] horizontal bands and every disc is in the band of its centre
//! (clamped: a disc below or above the box counts in the bottom or top band).
//! A contact whose two discs are in the same band or in neighbouring bands
//! belongs to the lower of the two, so a contact of band b touches only discs
//! of bands b and b + 1: no two even bands share a disc, nor do two odd ones.
//! The contacts are resolved in three phases,
//!
//! 1. every even band, side by side,
//! 2. every odd band, side by side,
//! 3. the contacts whose discs are further apart than neighbouring bands (a
//!    pair across a periodic edge, or discs larger than a band), on one thread,
//!
//! and within a band in ascending pair order. That the bands of a phase share
//! no disc follows from how keys are given, whatever the positions are (even
//! NaN), which is what makes the unsynchronised access in [`DiscsPtr`] sound.
//!
//! The order is fixed by the data (the discs' positions when resolution
//! starts), never by the thread count, and the serial code resolves in the same
//! order, so a run is the same bit for bit on any number of threads. Grouping
//! reads each disc's band from its height ([`band_of`]) before anything
//! moves; the narrow phase knows nothing of bands.
//!
//! Below [`BANDED_MIN_CONTACTS`] contacts the order is plain ascending pair
//! order ([`super::resolve_contacts`]): on one thread, or from
//! [`super::SPANS_MIN_CONTACTS`] on, in parallel with the same result by
//! spans of discs ([`super::spans`]). Measured on a crowded
//! gas (70 % area, `impulse` / grid, resolution stage in ns per disc-step,
//! medians of 5–7 runs, two threads against ascending order on one):
//!
//! | discs | contacts per step | ascending | banded, 2 threads |
//! |---:|---:|---:|---:|
//! | 10⁴ | 940 | 4.5 | 4.1 |
//! | 10⁵ | 10,400 | 5.9 | 6.3 |
//! | 2·10⁵ | 21,000 | 7.5 | 8.0 |
//! | 4·10⁵ | 44,000 | 11.3 | 7.1 |
//! | 10⁶ | 106,000 | 12.8 | 8.8 |
//!
//! Resolution waits on memory (about 100 ns per contact at 10⁶ discs), and
//! grouping costs about 15 ns per contact, so bands pay from a few tens of
//! thousands of contacts per step. On one thread banded order costs the same
//! as ascending at 10⁶ discs (10.4 against 10.8).

use super::{pair_mut, resolve_contact, ResolutionReport, Rule};
use crate::ledger::Ledger;
use crate::narrow_phase::Contact;
use crate::particle::Particle;
#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Horizontal bands the world's height is cut into: 32 per phase, enough to
/// keep many threads busy, few enough that a band holds many contacts.
pub const BANDS: usize = 64;

/// From this many contacts, resolution goes band by band (and on rayon's pool
/// when the step runs in parallel); below it, in ascending pair order.
pub const BANDED_MIN_CONTACTS: usize = 32_768;

/// The key of a contact whose discs are not in the same or neighbouring bands.
const APART: usize = BANDS;

/// Resolution by bands, with its reusable scratch: the contacts grouped by band.
#[derive(Clone, Debug)]
pub struct Banded {
    /// From this many contacts on, resolve by bands ([`BANDED_MIN_CONTACTS`];
    /// the tests lower it).
    min_contacts: usize,
    /// Per contact, its band, or [`APART`].
    keys: Vec<u8>,
    /// Per disc, the band it was claimed in while grouping.
    disc_bands: Vec<u8>,
    /// Contact indices, grouped by key, ascending within a group.
    order: Vec<u32>,
    /// Group `k` is `order[starts[k]..starts[k + 1]]`.
    starts: Vec<usize>,
}

impl Default for Banded {
    fn default() -> Self {
        Banded {
            min_contacts: BANDED_MIN_CONTACTS,
            keys: Vec::new(),
            disc_bands: Vec::new(),
            order: Vec::new(),
            starts: Vec::new(),
        }
    }
}

impl Banded {
    /// Resolves `contacts` like [`super::resolve_contacts`] does, but from
    /// [`BANDED_MIN_CONTACTS`] contacts on band by band (see the module doc): side by
    /// side on rayon's pool if `parallel` and the ledger is off, otherwise on
    /// this thread in the same order (so the ledger records collisions in the
    /// order they were resolved). Either way the result is the same.
    pub fn resolve(
        &mut self,
        particles: &mut [Particle],
        (contacts, height): (&[Contact], f64),
        law: super::ContactLaw,
        rule: Rule,
        (ledger, time): (&mut Ledger, f64),
        parallel: bool,
    ) -> ResolutionReport {
        if contacts.len() < self.min_contacts {
            #[cfg(feature = "parallel")]
            if parallel
                && !ledger.is_on()
                && contacts.len() >= super::spans::SPANS_MIN_CONTACTS
                && rayon::current_num_threads() > 1
            {
                let by_spans = super::spans::resolve_by_spans(particles, contacts, law, rule);
                if let Some(report) = by_spans {
                    return report;
                }
            }
            return super::resolve_contacts(particles, contacts, law, rule, ledger, time);
        }
        let band = |k: u32| band_of(particles[k as usize].pos.y, height);
        self.group(particles.len(), contacts, |_, c| [band(c.i), band(c.j)]);
        let mut report = ResolutionReport::default();
        let group = |k: usize| &self.order[self.starts[k]..self.starts[k + 1]];
        for parity in 0..2 {
            let band_of_phase = |k: usize| 2 * k + parity;
            crate::parallel::pool_or_here!(
                parallel && !ledger.is_on(),
                {
                    let discs = DiscsPtr::new(particles);
                    let phase = (0..BANDS / 2)
                        .into_par_iter()
                        .map(band_of_phase)
                        .map(|band| {
                            let mut report = ResolutionReport::default();
                            report.side_by_side += group(band).len();
                            for &k in group(band) {
                                let c = &contacts[k as usize];
                                // SAFETY: the bands of one phase share no disc
                                // (module doc), so no other thread touches discs
                                // `c.i` and `c.j` while this one holds them.
                                let (a, b) = unsafe { discs.pair(c.i as usize, c.j as usize) };
                                let off = (&mut Ledger::default(), time);
                                resolve_contact(a, b, c, law, rule, off, &mut report);
                            }
                            report
                        })
                        .reduce(ResolutionReport::default, ResolutionReport::merge);
                    report = report.merge(phase);
                },
                {
                    for band in (0..BANDS / 2).map(band_of_phase) {
                        resolve_serially(
                            particles,
                            contacts,
                            group(band),
                            law,
                            rule,
                            (ledger, time),
                            &mut report,
                        );
                    }
                }
            );
        }
        resolve_serially(
            particles,
            contacts,
            group(APART),
            law,
            rule,
            (ledger, time),
            &mut report,
        );
        report
    }

    /// Gives every contact its key and groups the contacts by key (a stable
    /// counting sort, so ascending pair order within a group).
    ///
    /// The bands come with the contacts (the narrow phase puts them there).
    /// Soundness does not rest on that: a disc keeps the first band a contact
    /// gives it, and a contact that disagrees, or whose bands are not the same
    /// or neighbours, is resolved with the serial rest.
    /// Sorts the contacts into bands: `bands_of(k, contact)` gives the
    /// bands its two discs are in (from their heights, when resolving).
    fn group(
        &mut self,
        disc_count: usize,
        contacts: &[Contact],
        bands_of: impl Fn(usize, &Contact) -> [u8; 2],
    ) {
        const UNSEEN: u8 = u8::MAX;
        self.disc_bands.clear();
        self.disc_bands.resize(disc_count, UNSEEN);
        let discs = &mut self.disc_bands;
        let mut claim = |disc: u32, band: u8| {
            let seen = &mut discs[disc as usize];
            if *seen == UNSEEN {
                *seen = band;
            }
            *seen == band
        };
        self.keys.clear();
        self.keys.extend(contacts.iter().enumerate().map(|(k, c)| {
            let [a, b] = bands_of(k, c);
            let in_bands = (a as usize) < BANDS && (b as usize) < BANDS && a.abs_diff(b) <= 1;
            if in_bands && claim(c.i, a) && claim(c.j, b) {
                a.min(b)
            } else {
                APART as u8
            }
        }));
        let mut starts = [0usize; BANDS + 2];
        for &k in &self.keys {
            starts[k as usize + 1] += 1;
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        self.starts.clear();
        self.starts.extend_from_slice(&starts);
        self.order.resize(contacts.len(), 0);
        let mut next = starts;
        for (index, &k) in self.keys.iter().enumerate() {
            self.order[next[k as usize]] = index as u32;
            next[k as usize] += 1;
        }
    }
}

/// The band of a disc whose centre is at height `y` in a world `height`
/// metres high: `y` cut into [`BANDS`] equal bands, a disc below the world
/// (or at NaN) in band 0, above it in the top band.
pub fn band_of(y: f64, height: f64) -> u8 {
    // A saturating cast: negative and NaN give 0.
    ((y * (BANDS as f64 / height)) as usize).min(BANDS - 1) as u8
}

/// Resolves the contacts `indices` of `contacts` in that order on this thread.
fn resolve_serially(
    particles: &mut [Particle],
    contacts: &[Contact],
    indices: &[u32],
    law: super::ContactLaw,
    rule: Rule,
    (ledger, time): (&mut Ledger, f64),
    report: &mut ResolutionReport,
) {
    for &k in indices {
        let c = &contacts[k as usize];
        let (a, b) = pair_mut(particles, c.i as usize, c.j as usize);
        resolve_contact(a, b, c, law, rule, (&mut *ledger, time), report);
    }
}

/// The discs, shared by the threads of one phase, each of which takes only
/// discs that no other takes (the bands' guarantee).
#[derive(Clone, Copy)]
#[cfg(feature = "parallel")]
struct DiscsPtr {
    first: *mut Particle,
    len: usize,
}

// SAFETY: `DiscsPtr` is only used inside one phase, whose threads touch
// disjoint sets of discs (see `Banded::resolve`), while the slice it came
// from is mutably borrowed by that phase and used by nothing else.
#[cfg(feature = "parallel")]
unsafe impl Send for DiscsPtr {}
#[cfg(feature = "parallel")]
unsafe impl Sync for DiscsPtr {}

#[cfg(feature = "parallel")]
impl DiscsPtr {
    fn new(particles: &mut [Particle]) -> Self {
        DiscsPtr {
            first: particles.as_mut_ptr(),
            len: particles.len(),
        }
    }

    /// Discs `i` and `j`, mutably.
    ///
    /// # Safety
    /// While the references live, no other thread may use disc `i` or `j`.
    #[allow(clippy::mut_from_ref)]
    unsafe fn pair(&self, i: usize, j: usize) -> (&mut Particle, &mut Particle) {
        assert!(
            i != j && i < self.len && j < self.len,
            "a contact joins two discs of the slice"
        );
        // SAFETY: both in bounds and distinct, so the two references do not
        // alias each other; the caller rules out every other alias.
        unsafe { (&mut *self.first.add(i), &mut *self.first.add(j)) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad_phase::BroadPhaseKind;
    use crate::narrow_phase::find_contacts;
    use crate::particle::Color;
    use crate::Boundary;
    use glam::DVec2;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    const SIZE: DVec2 = DVec2::new(40.0, 40.0);

    /// `n` discs of mixed sizes and masses thrown into a box too small for
    /// them, so that most overlap several others.
    fn crowd(n: usize, seed: u64) -> Vec<Particle> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        (0..n)
            .map(|k| {
                let pos = DVec2::new(rng.random_range(0.0..SIZE.x), rng.random_range(0.0..SIZE.y));
                let vel = DVec2::new(rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0));
                let radius = rng.random_range(0.3..0.8);
                Particle::new(pos, vel, radius * radius, radius, Color::palette(k))
            })
            .collect()
    }

    fn contacts_of(particles: &[Particle], boundary: Boundary) -> Vec<Contact> {
        let mut pairs = Vec::new();
        BroadPhaseKind::Grid
            .build()
            .candidate_pairs(particles, boundary, SIZE, &mut pairs);
        let mut contacts = Vec::new();
        find_contacts(particles, &pairs, boundary, SIZE, &mut contacts);
        contacts
    }

    fn always_banded() -> Banded {
        Banded {
            min_contacts: 0,
            ..Banded::default()
        }
    }

    fn bits(particles: &[Particle]) -> Vec<[u64; 4]> {
        let b = |p: &Particle| {
            [
                p.pos.x.to_bits(),
                p.pos.y.to_bits(),
                p.vel.x.to_bits(),
                p.vel.y.to_bits(),
            ]
        };
        particles.iter().map(b).collect()
    }

    #[cfg(feature = "parallel")]
    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool")
    }

    #[test]
    fn the_bands_of_a_phase_share_no_disc_whatever_bands_the_contacts_carry() {
        // Bands at random, many of them inconsistent (one disc in several
        // bands) or out of range: grouping alone must keep each phase apart.
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let discs = 300u32;
        let (contacts, bands): (Vec<Contact>, Vec<[u8; 2]>) = (0..5000)
            .map(|_| {
                let i = rng.random_range(0..discs - 1);
                let j = rng.random_range(i + 1..discs);
                let band = |rng: &mut ChaCha8Rng| rng.random_range(0..BANDS as u8 + 3);
                let contact = Contact {
                    i,
                    j,
                    normal: DVec2::X,
                    depth: 0.1,
                    relative_velocity: DVec2::ZERO,
                };
                (contact, [band(&mut rng), band(&mut rng)])
            })
            .unzip();
        let mut banded = always_banded();
        banded.group(discs as usize, &contacts, |k, _| bands[k]);
        let mut seen: Vec<usize> = banded.order.iter().map(|&k| k as usize).collect();
        seen.sort_unstable();
        assert_eq!(
            seen,
            (0..contacts.len()).collect::<Vec<_>>(),
            "every contact once"
        );
        let mut grouped = 0;
        for parity in 0..2 {
            let mut owner = vec![usize::MAX; discs as usize];
            for band in (parity..BANDS).step_by(2) {
                let group = &banded.order[banded.starts[band]..banded.starts[band + 1]];
                assert!(
                    group.windows(2).all(|w| w[0] < w[1]),
                    "pair order within a band"
                );
                grouped += group.len();
                for &k in group {
                    let c = &contacts[k as usize];
                    for disc in [c.i, c.j] {
                        let o = &mut owner[disc as usize];
                        assert!(
                            *o == usize::MAX || *o == band,
                            "disc {disc} in bands {o} and {band}"
                        );
                        *o = band;
                    }
                }
            }
        }
        assert!(
            grouped > 0 && grouped < contacts.len(),
            "some contacts in bands, some apart"
        );
    }

    #[test]
    #[cfg(feature = "parallel")]
    fn side_by_side_is_bit_for_bit_the_serial_banded_order_on_any_pool() {
        for boundary in [Boundary::Box, Boundary::Periodic] {
            let start = crowd(3000, 7);
            let contacts = contacts_of(&start, boundary);
            assert!(
                contacts.len() > 1000,
                "a crowd: {} contacts",
                contacts.len()
            );
            let run = |threads: usize, parallel: bool| {
                let mut particles = start.clone();
                let report = pool(threads).install(|| {
                    let ledger = (&mut Ledger::default(), 0.0);
                    always_banded().resolve(
                        &mut particles,
                        (&contacts, SIZE.y),
                        super::super::ContactLaw::smooth(0.9, 0.0),
                        Rule::IMPULSE,
                        ledger,
                        parallel,
                    )
                });
                // Side by side or not, the same result.
                let report = ResolutionReport {
                    side_by_side: 0,
                    ..report
                };
                (bits(&particles), report)
            };
            let serial = run(1, false);
            assert_eq!(run(1, true), serial);
            assert_eq!(run(2, true), serial);
            // The order is not ascending pair order: resolving it is a real change.
            let mut ascending = start.clone();
            let off = &mut Ledger::default();
            super::super::resolve_contacts(
                &mut ascending,
                &contacts,
                super::super::ContactLaw::smooth(0.9, 0.0),
                Rule::IMPULSE,
                off,
                0.0,
            );
            assert_ne!(bits(&ascending), serial.0);
        }
    }

    #[test]
    #[cfg(feature = "parallel")]
    fn banded_resolution_keeps_momentum_and_the_centre_of_mass() {
        let start = crowd(3000, 11);
        let contacts = contacts_of(&start, Boundary::Box);
        let totals = |ps: &[Particle]| {
            let mass: f64 = ps.iter().map(|p| p.mass).sum();
            let momentum: DVec2 = ps.iter().map(|p| p.mass * p.vel).sum();
            let moment: DVec2 = ps.iter().map(|p| p.mass * p.pos).sum();
            (
                momentum,
                moment / mass,
                ps.iter().map(|p| p.mass * p.vel.length()).sum::<f64>(),
            )
        };
        let (p0, c0, scale) = totals(&start);
        let mut particles = start.clone();
        let report = pool(2).install(|| {
            let ledger = (&mut Ledger::default(), 0.0);
            always_banded().resolve(
                &mut particles,
                (&contacts, SIZE.y),
                super::super::ContactLaw::smooth(1.0, 0.0),
                Rule::IMPULSE,
                ledger,
                true,
            )
        });
        let (p1, c1, _) = totals(&particles);
        assert!((p1 - p0).length() <= 1e-12 * scale, "momentum {p0} -> {p1}");
        assert!(
            (c1 - c0).length() <= 1e-12 * SIZE.x,
            "centre of mass {c0} -> {c1}"
        );
        let deepest = contacts.iter().map(|c| c.depth).fold(0.0, f64::max);
        assert_eq!(report.max_overlap, deepest);
        assert!(report.collisions > 0 && report.collisions <= contacts.len());
    }

    #[test]
    #[cfg(feature = "parallel")]
    fn the_ledger_records_the_banded_order_and_forces_no_other_result() {
        let start = crowd(2000, 13);
        let contacts = contacts_of(&start, Boundary::Box);
        let (mut quiet, mut recorded) = (start.clone(), start.clone());
        let mut ledger = Ledger::default();
        ledger.keep(usize::MAX);
        let (a, b) = pool(2).install(|| {
            let off = (&mut Ledger::default(), 0.0);
            let a = always_banded().resolve(
                &mut quiet,
                (&contacts, SIZE.y),
                super::super::ContactLaw::smooth(1.0, 0.0),
                Rule::IMPULSE,
                off,
                true,
            );
            let on = (&mut ledger, 0.0);
            let b = always_banded().resolve(
                &mut recorded,
                (&contacts, SIZE.y),
                super::super::ContactLaw::smooth(1.0, 0.0),
                Rule::IMPULSE,
                on,
                true,
            );
            (a, b)
        });
        assert_eq!(bits(&quiet), bits(&recorded));
        assert!(a.side_by_side > 0, "quiet: side by side");
        assert_eq!(b.side_by_side, 0, "recorded: in order on one thread");
        assert_eq!(
            ResolutionReport {
                side_by_side: 0,
                ..a
            },
            b
        );
        assert_eq!(ledger.entries().count(), b.collisions);
    }

    #[test]
    fn below_the_threshold_contacts_go_in_ascending_pair_order() {
        let start = crowd(600, 17);
        let contacts = contacts_of(&start, Boundary::Box);
        assert!(contacts.len() < BANDED_MIN_CONTACTS);
        let (mut banded, mut ascending) = (start.clone(), start.clone());
        let off = (&mut Ledger::default(), 0.0);
        Banded::default().resolve(
            &mut banded,
            (&contacts, SIZE.y),
            super::super::ContactLaw::smooth(0.8, 0.0),
            Rule::SEED,
            off,
            true,
        );
        super::super::resolve_contacts(
            &mut ascending,
            &contacts,
            super::super::ContactLaw::smooth(0.8, 0.0),
            Rule::SEED,
            &mut Ledger::default(),
            0.0,
        );
        assert_eq!(bits(&banded), bits(&ascending));
    }

    #[test]
    fn a_disc_is_in_the_band_of_its_height_clamped_to_the_world() {
        assert_eq!(band_of(0.0, 64.0), 0);
        assert_eq!(band_of(1.5, 64.0), 1);
        assert_eq!(band_of(63.9, 64.0), 63);
        assert_eq!(band_of(1e9, 64.0), BANDS as u8 - 1);
        assert_eq!(band_of(-5.0, 64.0), 0);
        assert_eq!(band_of(f64::NAN, 64.0), 0);
        assert_eq!(band_of(f64::INFINITY, 64.0), BANDS as u8 - 1);
    }
}
