//! Narrow phase, the second stage: which candidate pairs really overlap.
//!
//! For each overlapping pair it records the unit normal n̂ from the first disc
//! to the second, the overlap depth and the pair's relative velocity. Coincident centres have no direction
//! of their own; they get the fixed normal +x, so the result is deterministic
//! and never NaN.
//!
//! Each pair is tested on its own, so for large scenes the pairs are cut into
//! chunks of [`PAIR_CHUNK`] that rayon tests in parallel
//! ([`find_contacts_in_chunks`]); joined in chunk order, the contacts are the
//! same list, in the same order, as [`find_contacts`] makes.

use crate::boundary::Boundary;
use crate::broad_phase::{KeptCheck, Pair};
use crate::parallel::PAIR_CHUNK;
use crate::particle::Particle;
use glam::DVec2;
use std::sync::atomic::{AtomicBool, Ordering};

/// Two overlapping discs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// Index of the first disc.
    pub i: u32,
    /// Index of the second disc (`i < j`).
    pub j: u32,
    /// Unit normal pointing from disc `i` to disc `j`.
    pub normal: DVec2,
    /// How far the discs overlap: r₁ + r₂ − distance (> 0).
    pub depth: f64,
    /// Velocity of disc `j` relative to disc `i` when the contact was found,
    /// before any impulse of the pass that resolves it: what
    /// [`crate::resolution`] rewinds the pair along to the moment it touched.
    pub relative_velocity: DVec2,
}

/// How many pairs ahead the narrow phase asks for a disc. A million discs,
/// one thread, alternating runs: 13.2–13.5 ns per disc-step at 16 pairs,
/// 11.7–12.3 at 48 (32 to 96 alike), 15.0–15.7 at 8.
const AHEAD: usize = 48;
/// From how many discs it does: about where they outgrow the last cache
/// (72 bytes each; at 10⁵ discs prefetching made the stage 13 % slower).
const PREFETCH_FROM: usize = 200_000;

/// Pairs per block of [`find_contacts_checked`]: about 200 discs' worth,
/// which stay in the first-level cache between their check and their pairs.
const CHECK_BLOCK: usize = 256;

/// How many pairs ahead [`find_contacts_checked`] asks for a pair's second
/// disc, from [`PREFETCH_FROM`] discs. A million discs, one thread, 3
/// alternating runs: 13.0–14.7 ns per disc-step at 16, 11.2–11.3 at 48,
/// 10.8–11.4 at 96, 10.4–10.9 at 192, 11.0–11.6 at 384.
const CHECKED_AHEAD: usize = 192;

/// The normal used when two centres coincide.
pub const COINCIDENT_NORMAL: DVec2 = DVec2::X;

/// Replaces `out` with the contacts among `pairs`, in the order of `pairs`.
pub fn find_contacts(
    particles: &[Particle],
    pairs: &[Pair],
    boundary: Boundary,
    size: DVec2,
    out: &mut Vec<Contact>,
) {
    out.clear();
    let contact = |pair: &Pair| contact_of(particles, pair, boundary, size);
    if particles.len() < PREFETCH_FROM {
        out.extend(pairs.iter().filter_map(contact));
    } else {
        // The disc a pair some way ahead will read is asked for now:
        // beyond the caches the loop otherwise waits on each (a million
        // discs: the stage 1.4× faster; from the cache it was slower).
        let ahead = &pairs[AHEAD.min(pairs.len())..];
        contacts_prefetching(particles, (pairs, ahead), contact, out);
    }
}

/// The contacts among `run` (as `contact` finds them) onto `out`, asking
/// as each pair is tested for the second disc of the pair at the same
/// place in `ahead` (the pairs some way further on).
#[inline(always)]
fn contacts_prefetching(
    particles: &[Particle],
    (run, ahead): (&[Pair], &[Pair]),
    contact: impl Fn(&Pair) -> Option<Contact>,
    out: &mut Vec<Contact>,
) {
    let ahead = ahead.iter().map(Some).chain(std::iter::repeat(None));
    for (pair, next) in run.iter().zip(ahead) {
        if let Some(next) = next {
            crate::parallel::prefetch(&particles[next.j as usize]);
        }
        if let Some(found) = contact(pair) {
            out.push(found);
        }
    }
}

/// [`find_contacts`] over a kept list (a Verlet list) whose discs have not
/// been checked yet: checks each disc against `check` as the pairs reach it
/// (they come in the order of their first disc), so that the discs are read
/// once for both instead of twice (a million discs: the check was a pass
/// of 3.3 ns per disc of its own). Returns false, with `out` incomplete, at
/// the first disc that fails; true, with the very contacts
/// [`find_contacts`] gives, if all hold.
pub fn find_contacts_checked(
    particles: &[Particle],
    pairs: &[Pair],
    check: &KeptCheck,
    out: &mut Vec<Contact>,
) -> bool {
    let failed = AtomicBool::new(false);
    check_and_find(particles, pairs, 0..particles.len(), (check, &failed), out)
}

/// [`find_contacts_checked`] on rayon's pool, chunk by chunk like
/// [`find_contacts_in_chunks`]: each chunk checks the discs from its first
/// pair's first disc to the next chunk's (the first chunk from disc 0, the
/// last to the end), so that together they check every disc.
pub fn find_contacts_in_chunks_checked(
    particles: &[Particle],
    pairs: &[Pair],
    check: &KeptCheck,
    chunks: &mut Vec<Vec<Contact>>,
    out: &mut Vec<Contact>,
) -> bool {
    out.clear();
    let count = pairs.len().div_ceil(PAIR_CHUNK);
    chunks.resize_with(count, Vec::new);
    let n = particles.len();
    // Set by the first chunk that finds a disc out of its place, so that
    // the others stop too: everything found is thrown away then.
    let failed = AtomicBool::new(false);
    let first_disc = |c: usize| match c {
        0 => 0,
        c if c >= count => n,
        c => pairs[c * PAIR_CHUNK].i as usize,
    };
    let find = |c: usize, found: &mut Vec<Contact>| {
        let mine = &pairs[c * PAIR_CHUNK..((c + 1) * PAIR_CHUNK).min(pairs.len())];
        check_and_find(
            particles,
            mine,
            first_disc(c)..first_disc(c + 1),
            (check, &failed),
            found,
        )
    };
    let holds = crate::parallel::pool_or_here!(
        true,
        {
            let per_thread = crate::parallel::on_each_part(chunks, 1, |first, founds| {
                let mut found = founds.iter_mut().enumerate();
                found.all(|(k, found)| find(first + k, found))
            });
            per_thread.into_iter().all(|holds| holds)
        },
        {
            let mut found = chunks.iter_mut().enumerate();
            found.all(|(c, found)| find(c, found))
        }
    );
    let holds = holds && (count > 0 || check_and_find(particles, &[], 0..n, (check, &failed), out));
    if holds {
        for found in chunks.iter() {
            out.extend_from_slice(found);
        }
    }
    holds
}

/// The contacts among `pairs` into `out`, checking as it goes the discs
/// `discs` (which hold the first discs of `pairs`, and maybe more) against
/// `check`; false at the first that fails, which it tells `failed`, and
/// false as soon as `failed` says another chunk has (checked block by
/// block: on two threads a failed step took 1.3× as long as on one, each
/// thread going on to a failure of its own or to its end).
fn check_and_find(
    particles: &[Particle],
    pairs: &[Pair],
    discs: std::ops::Range<usize>,
    (check, failed): (&KeptCheck, &AtomicBool),
    out: &mut Vec<Contact>,
) -> bool {
    out.clear();
    let (boundary, size) = (check.boundary, check.size);
    let contact = |pair: &Pair| contact_of(particles, pair, boundary, size);
    let holds = |span: std::ops::Range<usize>| {
        let discs = particles[span.clone()].iter().zip(span);
        let all = discs.fold(true, |holds, (p, k)| holds & check.holds(k, p));
        if !all {
            failed.store(true, Ordering::Relaxed);
        }
        all && !failed.load(Ordering::Relaxed)
    };
    // Discs from `discs.start` to `checked` hold.
    let mut checked = discs.start;
    let prefetching = particles.len() >= PREFETCH_FROM;
    // A block of pairs at a time: first its discs (the first ones of its
    // pairs) are checked in one tight loop, then its pairs are tested,
    // reading those discs again from the first-level cache. (Checked pair
    // by pair, the check's loop, one to three discs per pair, is a branch
    // the processor cannot guess: 2.4× slower at 10⁵ discs, 6 % at 10⁶.)
    for (b, block) in pairs.chunks(CHECK_BLOCK).enumerate() {
        let last = block.last().map_or(0, |pair| pair.i as usize + 1);
        if last > checked {
            if !holds(checked..last) {
                return false;
            }
            checked = last;
        }
        if prefetching {
            // Beyond the caches: the second disc of a pair most of a block
            // ahead is asked for now.
            let ahead = &pairs[(b * CHECK_BLOCK + CHECKED_AHEAD).min(pairs.len())..];
            contacts_prefetching(particles, (block, ahead), contact, out);
        } else {
            out.extend(block.iter().filter_map(contact));
        }
    }
    checked >= discs.end || holds(checked..discs.end)
}

/// The contact of a candidate pair, if its discs overlap.
#[inline]
fn contact_of(
    particles: &[Particle],
    &Pair { i, j }: &Pair,
    boundary: Boundary,
    size: DVec2,
) -> Option<Contact> {
    let (a, b) = (&particles[i as usize], &particles[j as usize]);
    contact_between(a, b, boundary, size).map(|(normal, depth)| Contact {
        i,
        j,
        normal,
        depth,
        relative_velocity: b.vel - a.vel,
    })
}

/// [`find_contacts`] on rayon's pool: each chunk of [`PAIR_CHUNK`] pairs
/// into its own buffer in `chunks` (kept between calls), then the buffers
/// joined in chunk order into `out`.
pub fn find_contacts_in_chunks(
    particles: &[Particle],
    pairs: &[Pair],
    boundary: Boundary,
    size: DVec2,
    chunks: &mut Vec<Vec<Contact>>,
    out: &mut Vec<Contact>,
) {
    chunks.resize_with(pairs.len().div_ceil(PAIR_CHUNK), Vec::new);
    let find = |(pairs, found): (&[Pair], &mut Vec<Contact>)| {
        find_contacts(particles, pairs, boundary, size, found)
    };
    crate::parallel::pool_or_here!(
        true,
        {
            // Each thread the same run of chunks every step: pairs come in
            // the order of their first disc, so that is mostly the discs
            // its integration keeps in its caches.
            crate::parallel::on_each_part(chunks, 1, |first, founds| {
                let mine = pairs.chunks(PAIR_CHUNK).skip(first);
                mine.zip(founds.iter_mut()).for_each(find);
            });
        },
        {
            pairs
                .chunks(PAIR_CHUNK)
                .zip(chunks.iter_mut())
                .for_each(find);
        }
    );
    out.clear();
    for found in chunks.iter() {
        out.extend_from_slice(found);
    }
}

/// The normal and depth if discs `a` and `b` overlap (touching is not overlap).
pub fn contact_between(
    a: &Particle,
    b: &Particle,
    boundary: Boundary,
    size: DVec2,
) -> Option<(DVec2, f64)> {
    let delta = boundary.separation(a.pos, b.pos, size);
    let reach = a.radius + b.radius;
    let dist_sq = delta.length_squared();
    if dist_sq >= reach * reach {
        return None;
    }
    let dist = dist_sq.sqrt();
    let normal = if dist > 0.0 {
        let n = delta / dist;
        if n.is_finite() {
            n
        } else {
            COINCIDENT_NORMAL
        }
    } else {
        COINCIDENT_NORMAL
    };
    Some((normal, reach - dist))
}
