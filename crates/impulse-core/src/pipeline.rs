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
use crate::narrow_phase::{find_contacts, find_contacts_in_chunks, Contact};
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
}

impl Pipeline {
    pub(crate) fn new(kind: BroadPhaseKind) -> Self {
        Pipeline {
            kind,
            broad_phase: kind.build(),
            pairs: Vec::new(),
            contacts: Vec::new(),
            parallel: false,
            contact_chunks: Vec::new(),
            walls: Vec::new(),
            banded: Default::default(),
            travels: Vec::new(),
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

    /// The broad phase: candidate pairs, whose boxes may touch.
    pub(crate) fn broad_phase(
        &mut self,
        particles: &[Particle],
        laws: &Laws,
        stats: &mut StepStats,
    ) {
        let lap = Lap::start();
        self.broad_phase.set_parallel(self.parallel);
        self.broad_phase
            .candidate_pairs(particles, laws.boundary, laws.size, &mut self.pairs);
        stats.candidate_pairs += self.pairs.len();
        stats.timings.broad_phase += lap.elapsed();
    }

    /// The narrow phase: the candidate pairs that overlap, as contacts
    /// (fills `self.contacts`).
    pub(crate) fn narrow_phase(
        &mut self,
        particles: &[Particle],
        laws: &Laws,
        stats: &mut StepStats,
    ) {
        let lap = Lap::start();
        if self.parallel {
            find_contacts_in_chunks(
                particles,
                &self.pairs,
                laws.boundary,
                laws.size,
                &mut self.contact_chunks,
                &mut self.contacts,
            );
        } else {
            find_contacts(
                particles,
                &self.pairs,
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
    /// had turned when it touched the wall; see [`crate::boundary::WallContact`]. It runs
    /// chunk by chunk, serially too, and the chunks' wall impulses are
    /// added in chunk order, so the sum does not depend on the threads;
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
        let (edges, gravity) = ((laws.size, laws.walls), laws.gravity);
        let e = (laws.wall_restitution, laws.wall_rough());
        let contact = WallContact {
            impact_speed: crate::impact::threshold(gravity, h),
            rewind: if at_touch { h } else { 0.0 },
        };
        let recording = ledger.is_on();
        parallel::map_chunks_mut(
            self.parallel,
            particles,
            |chunk| {
                let mut hits = Vec::new();
                let record = recording.then_some((&mut hits, time));
                let boundary = laws.boundary;
                let report = boundary.apply_recording(chunk, edges, gravity, e, contact, record);
                (report, hits)
            },
            &mut self.walls,
        );
        let mut impulse = 0.0;
        for (chunk, (w, hits)) in self.walls.iter().enumerate() {
            stats.wall_hits += w.hits;
            stats.resting_contacts += w.resting;
            impulse += w.impulse;
            for hit in hits {
                let disc = chunk * parallel::CHUNK + hit.disc;
                ledger.push(WallHit { disc, ..*hit });
            }
        }
        stats.wall_impulse += impulse;
        stats.timings.boundary += lap.elapsed();
    }
}
