//! The five stages with their reusable buffers, shared by the fixed-step
//! methods: [`Pipeline::broad_phase`] → [`Pipeline::narrow_phase`] →
//! [`Pipeline::resolve`] → [`Pipeline::integrate`] →
//! [`Pipeline::apply_boundary`]. Each stage adds its wall-clock time to the
//! step's [`StageTimings`](crate::stats::StageTimings). The world owns one
//! and runs a substep through it; the pipeline knows no method.

use crate::boundary::{WallContact, WallReport};
use crate::broad_phase::{BroadPhase, BroadPhaseKind, Pair};
use crate::laws::Laws;
use crate::ledger::{Ledger, WallHit};
use crate::narrow_phase::{
    find_contacts, find_contacts_checked, find_contacts_in_chunks, find_contacts_in_chunks_checked,
    Contact,
};
use crate::parallel;
use crate::particle::Particle;
use crate::resolution::{ResolutionReport, Rule};
use crate::stats::{Lap, StepStats};
use glam::DVec2;

/// Detection stages and their reusable buffers.
pub(crate) struct Pipeline {
    pub(crate) kind: BroadPhaseKind,
    broad_phase: Box<dyn BroadPhase + Send>,
    pairs: Vec<Pair>,
    /// Whether the broad phase keeps its own list (read in place) rather
    /// than filling `pairs`.
    kept: bool,
    /// The kept list was taken without checking the discs: the narrow
    /// phase checks them ([`BroadPhase::kept_unchecked`]).
    unchecked: bool,
    /// Contacts found by the last [`Pipeline::detect`].
    pub(crate) contacts: Vec<Contact>,
    /// Run the order-free stages on rayon's pool (the plan's choice).
    pub(crate) parallel: bool,
    /// Scratch: the narrow phase's contacts per chunk of pairs.
    contact_chunks: Vec<Vec<Contact>>,
    /// Scratch: what the walls did per chunk of discs, and the hits for
    /// the ledger (disc indices within the chunk; none while it is off).
    walls: Vec<(WallReport, Vec<WallHit>)>,
    /// Scratch: large contact lists grouped into bands for resolution.
    banded: crate::resolution::Banded,
    /// Scratch: the largest travel per chunk of discs in the integration.
    travels: Vec<f64>,
    /// Scratch: per chunk of the fused integration and boundary stage, what
    /// the walls did, the largest travel and the two stages' times.
    #[allow(clippy::type_complexity)]
    fused: Vec<(
        (WallReport, Vec<WallHit>),
        f64,
        (std::time::Duration, std::time::Duration),
    )>,
}

impl Pipeline {
    pub(crate) fn new(kind: BroadPhaseKind) -> Self {
        Pipeline {
            kind,
            broad_phase: kind.build(),
            pairs: Vec::new(),
            kept: false,
            unchecked: false,
            contacts: Vec::new(),
            parallel: false,
            contact_chunks: Vec::new(),
            walls: Vec::new(),
            banded: Default::default(),
            travels: Vec::new(),
            fused: Vec::new(),
        }
    }

    /// Switches to another broad phase (fresh buffers); returns whether it
    /// changed.
    pub(crate) fn use_kind(&mut self, kind: BroadPhaseKind) -> bool {
        let changed = kind != self.kind;
        if changed {
            *self = Pipeline::new(kind);
        }
        changed
    }

    /// Broad phase then narrow phase.
    pub(crate) fn detect(&mut self, particles: &[Particle], laws: &Laws, stats: &mut StepStats) {
        self.broad_phase(particles, laws, stats);
        self.narrow_phase(particles, laws, stats);
    }

    /// The broad phase: candidate pairs, whose boxes may touch. A kept list
    /// is taken as it stands and checked by the narrow phase
    /// ([`BroadPhase::kept_unchecked`]).
    pub(crate) fn broad_phase(
        &mut self,
        particles: &[Particle],
        laws: &Laws,
        stats: &mut StepStats,
    ) {
        let (boundary, size) = (laws.boundary, laws.size);
        self.unchecked = (self.broad_phase)
            .kept_unchecked(particles.len(), boundary, size)
            .is_some();
        if self.unchecked {
            self.kept = true;
        } else {
            self.refresh(particles, laws, stats);
        }
    }

    /// The broad phase proper: brings a kept list up to date, or makes the
    /// candidate pairs afresh.
    fn refresh(&mut self, particles: &[Particle], laws: &Laws, stats: &mut StepStats) {
        let lap = Lap::start();
        self.broad_phase.set_parallel(self.parallel);
        let (boundary, size) = (laws.boundary, laws.size);
        self.kept = self.broad_phase.refresh_kept(particles, boundary, size);
        if !self.kept {
            self.broad_phase
                .candidate_pairs(particles, boundary, size, &mut self.pairs);
        }
        stats.candidate_pairs += self.pairs().len();
        stats.timings.broad_phase += lap.elapsed();
    }

    /// The candidate pairs of the last broad phase.
    fn pairs(&self) -> &[Pair] {
        if self.kept {
            self.broad_phase.kept_pairs()
        } else {
            &self.pairs
        }
    }

    /// The narrow phase: the candidate pairs that overlap, as contacts
    /// (fills `self.contacts`).
    pub(crate) fn narrow_phase(
        &mut self,
        particles: &[Particle],
        laws: &Laws,
        stats: &mut StepStats,
    ) {
        if std::mem::take(&mut self.unchecked) {
            let lap = Lap::start();
            let (boundary, size) = (laws.boundary, laws.size);
            if let Some((pairs, check)) =
                self.broad_phase
                    .kept_unchecked(particles.len(), boundary, size)
            {
                let holds = if self.parallel {
                    let chunks = &mut self.contact_chunks;
                    find_contacts_in_chunks_checked(
                        particles,
                        pairs,
                        &check,
                        chunks,
                        &mut self.contacts,
                    )
                } else {
                    find_contacts_checked(particles, pairs, &check, &mut self.contacts)
                };
                let candidates = pairs.len();
                stats.timings.narrow_phase += lap.elapsed();
                if holds {
                    stats.candidate_pairs += candidates;
                    stats.contacts += self.contacts.len();
                    return;
                }
            }
            // A disc moved too far for the list (or was edited): the broad
            // phase brings it up to date, and the pairs are tested again.
            self.refresh(particles, laws, stats);
        }
        let lap = Lap::start();
        let pairs = if self.kept {
            self.broad_phase.kept_pairs()
        } else {
            &self.pairs[..]
        };
        if self.parallel {
            find_contacts_in_chunks(
                particles,
                pairs,
                laws.boundary,
                laws.size,
                &mut self.contact_chunks,
                &mut self.contacts,
            );
        } else {
            find_contacts(
                particles,
                pairs,
                laws.boundary,
                laws.size,
                &mut self.contacts,
            );
        }
        stats.contacts += self.contacts.len();
        stats.timings.narrow_phase += lap.elapsed();
    }

    /// The resolution stage over `self.contacts`: in ascending pair order, or
    /// band by band for large contact lists (on the pool if parallel; the
    /// same result either way, see [`crate::resolution::Banded`]), adding
    /// what it did to `stats`.
    pub(crate) fn resolve(
        &mut self,
        particles: &mut [Particle],
        (laws, h): (&Laws, f64),
        rule: Rule,
        ledger: (&mut Ledger, f64),
        stats: &mut StepStats,
    ) {
        let lap = Lap::start();
        let law = crate::resolution::ContactLaw {
            restitution: laws.restitution,
            impact_speed: crate::impact::threshold(laws.gravity, h),
            tangential: laws.rough(),
            substep: h,
        };
        let (contacts, parallel) = (&self.contacts, self.parallel);
        let report: ResolutionReport = self.banded.resolve(
            particles,
            (contacts, laws.size.y),
            law,
            rule,
            ledger,
            parallel,
        );
        stats.pair_collisions += report.collisions;
        stats.at_touch += report.at_touch;
        stats.at_touch_changed += report.at_touch_changed;
        stats.contacts_side_by_side += report.side_by_side;
        stats.resting_contacts += report.resting;
        stats.max_overlap = stats.max_overlap.max(report.max_overlap);
        stats.timings.resolution += lap.elapsed();
    }

    /// The integration stage (semi-implicit Euler), chunk by chunk; keeps
    /// the largest travel in [`StepStats::max_travel`].
    pub(crate) fn integrate(
        &mut self,
        particles: &mut [Particle],
        gravity: DVec2,
        h: f64,
        stats: &mut StepStats,
    ) {
        let lap = Lap::start();
        parallel::map_chunks_mut(
            self.parallel,
            particles,
            |chunk| crate::integration::integrate(chunk, gravity, h),
            &mut self.travels,
        );
        let travel = self.travels.iter().copied().fold(0.0, f64::max);
        stats.max_travel = stats.max_travel.max(travel);
        stats.timings.integration += lap.elapsed();
    }

    /// The boundary stage after a (sub)step of `h` seconds, adding what the
    /// walls did to `stats` and, when the ledger is on, each wall hit to it
    /// at `time` (the end of the (sub)step, when the walls act). With
    /// `at_touch` (the impulse method) a bouncing disc is placed as if it
    /// had turned when it touched the wall; see [`crate::boundary::WallContact`].
    /// It runs chunk by chunk, serially too, and the chunks' wall impulses
    /// are added in chunk order, so the sum does not depend on the threads;
    /// the hits go into the ledger in chunk order too.
    pub(crate) fn apply_boundary(
        &mut self,
        particles: &mut [Particle],
        laws: &Laws,
        (h, at_touch): (f64, bool),
        (ledger, time): (&mut Ledger, f64),
        stats: &mut StepStats,
    ) {
        let lap = Lap::start();
        let walls = Walls::of(laws, (h, at_touch), ledger.is_on(), time);
        parallel::map_chunks_mut(
            self.parallel,
            particles,
            |chunk| walls.apply(chunk),
            &mut self.walls,
        );
        book_walls(&self.walls, ledger, stats);
        stats.timings.boundary += lap.elapsed();
    }

    /// The integration stage then the boundary stage, chunk by chunk while
    /// a chunk is in cache (one pass over the discs instead of two): the
    /// same result, bit for bit, as [`Pipeline::integrate`] then
    /// [`Pipeline::apply_boundary`], since each disc's integration and
    /// boundary depend on that disc alone and the chunks are booked in
    /// order. The stage's time is shared between the two stages' timings
    /// as the chunks' own clocks split it.
    pub(crate) fn integrate_and_bound(
        &mut self,
        particles: &mut [Particle],
        laws: &Laws,
        (h, at_touch): (f64, bool),
        (ledger, time): (&mut Ledger, f64),
        stats: &mut StepStats,
    ) {
        let lap = Lap::start();
        let gravity = laws.gravity;
        let walls = Walls::of(laws, (h, at_touch), ledger.is_on(), time);
        parallel::map_chunks_mut(
            self.parallel,
            particles,
            |chunk| {
                let start = crate::clock::Instant::now();
                let travel = crate::integration::integrate(chunk, gravity, h);
                let moved = crate::clock::Instant::now();
                let walled = walls.apply(chunk);
                let split = (moved.duration_since(start), moved.elapsed());
                (walled, travel, split)
            },
            &mut self.fused,
        );
        let (mut travel, mut integrating, mut bounding) = (0.0f64, 0.0, 0.0);
        self.walls.clear();
        for (walled, t, (i, b)) in self.fused.drain(..) {
            self.walls.push(walled);
            travel = travel.max(t);
            integrating += i.as_secs_f64();
            bounding += b.as_secs_f64();
        }
        stats.max_travel = stats.max_travel.max(travel);
        book_walls(&self.walls, ledger, stats);
        let elapsed = lap.elapsed();
        let share = integrating / (integrating + bounding).max(f64::MIN_POSITIVE);
        let integration = elapsed.mul_f64(share.clamp(0.0, 1.0));
        stats.timings.integration += integration;
        stats.timings.boundary += elapsed - integration;
    }
}

/// The boundary stage's law for one (sub)step, applied chunk by chunk.
struct Walls {
    boundary: crate::boundary::Boundary,
    edges: (DVec2, crate::boundary::Walls),
    gravity: DVec2,
    law: (f64, crate::rough::Tangential),
    contact: WallContact,
    /// Record the hits (at this time) for the ledger.
    recording: Option<f64>,
}

impl Walls {
    fn of(laws: &Laws, (h, at_touch): (f64, bool), recording: bool, time: f64) -> Walls {
        Walls {
            boundary: laws.boundary,
            edges: (laws.size, laws.walls),
            gravity: laws.gravity,
            law: (laws.wall_restitution, laws.wall_rough()),
            contact: WallContact {
                impact_speed: crate::impact::threshold(laws.gravity, h),
                rewind: if at_touch { h } else { 0.0 },
            },
            recording: recording.then_some(time),
        }
    }

    /// What the walls did to one chunk, and its hits (disc indices within
    /// the chunk; none while the ledger is off).
    fn apply(&self, chunk: &mut [Particle]) -> (WallReport, Vec<WallHit>) {
        let mut hits = Vec::new();
        let record = self.recording.map(|time| (&mut hits, time));
        let report = self.boundary.apply_recording(
            chunk,
            self.edges,
            self.gravity,
            self.law,
            self.contact,
            record,
        );
        (report, hits)
    }
}

/// Adds what the walls did, chunk by chunk in order, to `stats`, and each
/// hit to `ledger` with its disc's index in the whole slice.
fn book_walls(walls: &[(WallReport, Vec<WallHit>)], ledger: &mut Ledger, stats: &mut StepStats) {
    let mut impulse = 0.0;
    for (chunk, (w, hits)) in walls.iter().enumerate() {
        stats.wall_hits += w.hits;
        stats.resting_contacts += w.resting;
        impulse += w.impulse;
        for hit in hits {
            let disc = chunk * parallel::CHUNK + hit.disc;
            ledger.push(WallHit { disc, ..*hit });
        }
    }
    stats.wall_impulse += impulse;
}
