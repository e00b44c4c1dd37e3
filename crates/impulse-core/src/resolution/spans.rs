//! Resolution of a small contact list on several threads, each thread on
//! the discs it integrates, in exactly the serial order's result.
//!
//! Lists too short to go by bands ([`super::BANDED_MIN_CONTACTS`]) are
//! resolved in ascending pair order. Two contacts that share no disc commute, so the only order
//! that matters is each disc's own: the contacts that touch it, in list
//! order. The discs are cut into the same contiguous spans the threads
//! integrate ([`crate::parallel::spans_of`] of [`crate::parallel::CHUNK`]),
//! and a contact whose two discs lie in one span is *local* to it.
//!
//! 1. Before anything moves, every disc of a contact that is not local
//!    (its discs in two spans) is marked.
//! 2. Each thread resolves, in list order, the local contacts of its own
//!    span, except that a contact touching a marked disc is left for later
//!    and marks its other disc too; once a thread has marked
//!    [`MARKED_HERE`] discs itself, it leaves the rest of its span's
//!    contacts for later.
//! 3. What was left, and the contacts that are not local, are resolved on
//!    one thread in list order.
//!
//! A disc that stage 2 touches is touched by no other thread, and every
//! contact left for later comes, for each of its discs, after every contact
//! stage 2 resolved on that disc: so each disc sees its contacts in list
//! order, and the result is the serial one bit for bit on any number of
//! threads. The list must come in order of first disc (as the grid's
//! pairs do), so that each span's contacts are one stretch of it. Discs
//! numbered in the order they lie in space (the presets' gases) have few
//! contacts across spans; where more than a quarter are, or the list is not
//! in order, it is resolved serially instead.
//!
//! At 10⁵ discs (the bench's gas, about 775 contacts a step, two threads)
//! resolution went from 3.8–4.1 to 2.8–2.9 ms per 200 steps: the thread
//! handing out the work and the serial rest take what halving would have
//! saved beyond that.

#[cfg(feature = "parallel")]
use super::{resolve_contact, ContactLaw, ResolutionReport, Rule};
#[cfg(feature = "parallel")]
use crate::{ledger::Ledger, narrow_phase::Contact, particle::Particle};

/// From this many contacts a list is shared out by spans: below, handing
/// it to the other thread costs more than the half it would take.
pub const SPANS_MIN_CONTACTS: usize = 256;

/// How many discs a thread marks itself (counting a disc marked twice
/// twice) before it leaves the rest of its contacts to the serial stage.
#[cfg(feature = "parallel")]
const MARKED_HERE: usize = 64;

/// Resolves `contacts` (ledger off, at least two threads) like
/// [`super::resolve_contacts`], the discs' spans side by side; `None`
/// (nothing touched) where the list is not in order of first disc, names
/// a disc past the slice's end, has fewer than two spans of discs with
/// contacts, or the spans too intertwined to gain (module doc).
#[cfg(feature = "parallel")]
pub fn resolve_by_spans(
    particles: &mut [Particle],
    contacts: &[Contact],
    law: ContactLaw,
    rule: Rule,
) -> Option<ResolutionReport> {
    use crate::parallel::{on_each_thread, spans_of, split_by, CHUNK};
    // In order of first disc (as the grid's pairs come), each span's
    // contacts are one stretch of the list.
    if !contacts.is_sorted_by_key(|c| c.i) {
        return None;
    }
    let spans = spans_of(particles.len(), CHUNK, rayon::current_num_threads());
    let stretches: Vec<&[Contact]> = spans
        .iter()
        .map(|span| {
            let first = contacts.partition_point(|c| (c.i as usize) < span.start);
            let end = contacts.partition_point(|c| (c.i as usize) < span.end);
            &contacts[first..end]
        })
        .collect();
    // Stage 1: the discs of the contacts across spans (their second disc
    // past the end of their first's span).
    // A contact whose first disc is past the slice is in no stretch, and
    // one whose second is would fail only after the threads ran: left to
    // the serial order, which fails at once.
    let n = particles.len();
    if contacts.last().is_some_and(|c| c.i as usize >= n) {
        return None;
    }
    // With fewer than two stretches, one thread would do it all.
    if stretches.iter().filter(|s| !s.is_empty()).count() < 2 {
        return None;
    }
    let mut marked: Vec<u32> = Vec::new();
    for (stretch, span) in stretches.iter().zip(&spans) {
        for c in stretch.iter().filter(|c| c.j as usize >= span.end) {
            if c.j as usize >= n {
                return None;
            }
            marked.extend([c.i, c.j]);
        }
    }
    if 2 * marked.len() > contacts.len() {
        return None;
    }
    marked.sort_unstable();
    // Stage 2: each span on the thread that integrates it.
    let parts: Vec<_> = split_by(particles, &spans)
        .into_iter()
        .zip(&spans)
        .zip(stretches)
        .collect();
    let marked = &marked;
    let per_span = on_each_thread(parts, |((discs, span), stretch)| {
        let first = span.start as u32;
        let mut report = ResolutionReport::default();
        let mut left: Vec<&Contact> = Vec::new();
        // Few, searched one by one; past `MARKED_HERE` the rest of the
        // stretch is left for later (which keeps each disc's order too).
        let mut also_marked: Vec<u32> = Vec::new();
        for (k, c) in stretch.iter().enumerate() {
            // As `resolve_contacts` does: a few contacts on, asked for now.
            if let Some(ahead) = stretch.get(k + super::PREFETCH_CONTACTS_AHEAD) {
                crate::parallel::prefetch(&discs[(ahead.i - first) as usize]);
                if let Some(other) = discs.get((ahead.j - first) as usize) {
                    crate::parallel::prefetch(other);
                }
            }
            let is_marked = |d: u32| {
                (!marked.is_empty() && marked.binary_search(&d).is_ok()) || also_marked.contains(&d)
            };
            if also_marked.len() > MARKED_HERE || is_marked(c.i) || is_marked(c.j) {
                if also_marked.len() <= MARKED_HERE {
                    also_marked.extend([c.i, c.j]);
                }
                left.push(c);
                continue;
            }
            let (a, b) = super::pair_mut(discs, (c.i - first) as usize, (c.j - first) as usize);
            let off = (&mut Ledger::default(), 0.0);
            resolve_contact(a, b, c, law, rule, off, &mut report);
            report.side_by_side += 1;
        }
        (report, left)
    });
    // Stage 3: the rest on this thread, in list order (the spans' in turn).
    let mut report = ResolutionReport::default();
    for (part, left) in per_span {
        report = report.merge(part);
        for c in left {
            let (a, b) = super::pair_mut(particles, c.i as usize, c.j as usize);
            resolve_contact(
                a,
                b,
                c,
                law,
                rule,
                (&mut Ledger::default(), 0.0),
                &mut report,
            );
        }
    }
    Some(report)
}

#[cfg(all(test, feature = "parallel"))]
mod tests {
    use super::*;
    use crate::parallel::CHUNK;
    use crate::particle::Color;
    use glam::DVec2;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// `n` discs in a row and contacts mostly between near neighbours in
    /// number (as in a gas numbered by place), some across the spans'
    /// edges (the deferred chains are `a_chain_after_…`'s).
    fn scene(n: usize, across: usize, seed: u64) -> (Vec<Particle>, Vec<Contact>) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let discs: Vec<Particle> = (0..n)
            .map(|k| {
                let pos = DVec2::new(k as f64, rng.random_range(0.0..1.0));
                let vel = DVec2::new(rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0));
                let radius = rng.random_range(0.3..0.8);
                Particle::new(pos, vel, radius * radius, radius, Color::palette(k))
            })
            .collect();
        let contact = |i: u32, j: u32, rng: &mut ChaCha8Rng| {
            let angle: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let (a, b) = (&discs[i as usize], &discs[j as usize]);
            Contact {
                i,
                j,
                normal: DVec2::from_angle(angle),
                depth: rng.random_range(0.0..0.05),
                relative_velocity: b.vel - a.vel,
            }
        };
        let mut contacts: Vec<Contact> = (0..2000)
            .map(|_| {
                let i = rng.random_range(0..n as u32 - 40);
                let j = i + rng.random_range(1..40);
                contact(i, j, &mut rng)
            })
            .collect();
        // Across a multiple of CHUNK, which every edge of the spans is
        // (not every multiple is an edge: some of these stay local).
        for _ in 0..across {
            let edge = CHUNK as u32 * rng.random_range(1..(n / CHUNK) as u32);
            let i = edge - rng.random_range(1..20);
            let j = edge + rng.random_range(0..20);
            let at = rng.random_range(0..contacts.len());
            contacts.insert(at, contact(i, j, &mut rng));
        }
        // In order of first disc, as the narrow phase gives them; the
        // second discs of one first disc stay in no order.
        contacts.sort_by_key(|c| c.i);
        (discs, contacts)
    }

    fn bits(particles: &[Particle]) -> Vec<[u64; 4]> {
        let b = |p: &Particle| p.pos.to_array().map(f64::to_bits);
        let v = |p: &Particle| p.vel.to_array().map(f64::to_bits);
        let join = |p: &Particle| [b(p)[0], b(p)[1], v(p)[0], v(p)[1]];
        particles.iter().map(join).collect()
    }

    /// Resolves `contacts` serially and by spans on `threads` threads,
    /// checks that both give the same discs bit for bit and the same
    /// report, and returns how many went side by side.
    fn side_by_side_as_serial(discs: &[Particle], contacts: &[Contact], threads: usize) -> usize {
        let law = ContactLaw::smooth(0.9, 0.0);
        let mut serial = discs.to_vec();
        let off = &mut Ledger::default();
        let want =
            super::super::resolve_contacts(&mut serial, contacts, law, Rule::IMPULSE, off, 0.0);
        let mut spans = discs.to_vec();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool");
        let got = pool
            .install(|| resolve_by_spans(&mut spans, contacts, law, Rule::IMPULSE))
            .expect("few contacts across the spans");
        let report = ResolutionReport {
            side_by_side: 0,
            ..got
        };
        assert_eq!(report, want, "{threads} threads");
        assert!(bits(&spans) == bits(&serial), "{threads} threads");
        assert!(
            bits(&spans) != bits(discs),
            "the contacts changed the discs"
        );
        got.side_by_side
    }

    #[test]
    fn spans_side_by_side_give_the_serial_result_bit_for_bit() {
        for (threads, across) in [(2, 0), (2, 40), (3, 40), (5, 200)] {
            let (discs, contacts) = scene(5 * CHUNK + 123, across, threads as u64);
            let shared = side_by_side_as_serial(&discs, &contacts, threads);
            assert!(
                shared > contacts.len() / 2,
                "{threads} threads, {across} across"
            );
        }
    }

    /// A contact across the edge of two spans, then a chain of contacts
    /// each sharing a disc with the one before: the whole chain waits, and
    /// past `MARKED_HERE` marked discs so does the rest of that span.
    #[test]
    fn a_chain_after_a_contact_across_the_spans_waits_whole() {
        let (discs, mut contacts) = scene(3 * CHUNK, 0, 4);
        // The first span's contacts keep clear of its last disc.
        contacts.retain(|c| (c.j as usize) < CHUNK - 1 || c.i as usize > CHUNK + 300);
        let edge = CHUNK as u32;
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        let mut touching = |i: u32, j: u32| Contact {
            i,
            j,
            normal: DVec2::from_angle(rng.random_range(0.0..std::f64::consts::TAU)),
            depth: 0.01,
            relative_velocity: discs[j as usize].vel - discs[i as usize].vel,
        };
        contacts.push(touching(edge - 1, edge));
        for k in 0..200 {
            contacts.push(touching(edge + k, edge + k + 1));
        }
        contacts.sort_by_key(|c| c.i);
        let first_span = contacts.iter().filter(|c| c.i < edge - 1).count();
        let later = contacts.iter().filter(|c| c.i > edge + 300).count();
        assert!(first_span > 500 && later > 500, "{first_span}, {later}");
        // Only the first span's own contacts went side by side.
        assert_eq!(side_by_side_as_serial(&discs, &contacts, 2), first_span);
    }

    #[test]
    fn discs_numbered_at_random_are_left_to_the_serial_order() {
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let (mut discs, _) = scene(3 * CHUNK, 0, 9);
        let n = discs.len() as u32;
        let mut contacts: Vec<Contact> = (0..500)
            .map(|_| {
                let (a, b) = (rng.random_range(0..n - 1), rng.random_range(0..n - 1));
                Contact {
                    i: a.min(b),
                    j: a.max(b) + u32::from(a == b),
                    normal: DVec2::X,
                    depth: 0.01,
                    relative_velocity: DVec2::ZERO,
                }
            })
            .collect();
        let before = bits(&discs);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("a pool");
        let law = ContactLaw::smooth(1.0, 0.0);
        let mut try_spans = |contacts: &[Contact]| {
            pool.install(|| resolve_by_spans(&mut discs, contacts, law, Rule::IMPULSE))
        };
        assert!(try_spans(&contacts).is_none(), "not in order of first disc");
        contacts.sort_by_key(|c| c.i);
        let got = try_spans(&contacts);
        assert!(
            got.is_none(),
            "nearly half the contacts cross the spans' edge"
        );
        assert!(bits(&discs) == before, "nothing touched");
    }

    #[test]
    fn lists_one_thread_would_do_alone_or_past_the_discs_are_left_alone() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("a pool");
        let law = ContactLaw::smooth(1.0, 0.0);
        // Whether it went by spans, and whether it left the discs alone.
        let try_spans = |discs: &mut Vec<Particle>, contacts: &[Contact]| {
            let before = bits(discs);
            let got = pool.install(|| resolve_by_spans(discs, contacts, law, Rule::IMPULSE));
            (got.is_some(), bits(discs) == before)
        };
        // Fewer discs than a chunk: one span holds them all.
        let (mut few, contacts) = scene(CHUNK - 100, 0, 5);
        assert_eq!(try_spans(&mut few, &contacts), (false, true), "one span");
        // A second disc, or a first, past the end of the slice.
        let (mut discs, contacts) = scene(3 * CHUNK, 0, 6);
        let n = discs.len() as u32;
        let past = |i: u32, j: u32| Contact {
            i,
            j,
            normal: DVec2::X,
            depth: 0.01,
            relative_velocity: DVec2::ZERO,
        };
        for bad in [past(n - 2, n + 5), past(n + 1, n + 2)] {
            let mut with_bad = contacts.clone();
            with_bad.push(bad);
            with_bad.sort_by_key(|c| c.i);
            assert_eq!(try_spans(&mut discs, &with_bad), (false, true), "{bad:?}");
        }
        let alone = try_spans(&mut discs, &contacts);
        assert_eq!(alone, (true, false), "the list itself goes by spans");
    }
}
