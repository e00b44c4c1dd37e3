//! The event queue: one slot per disc holding its earliest predicted event,
//! so re-predicting a disc replaces its old event instead of leaving a stale
//! copy behind.
//!
//! It is a calendar queue (Brown 1988; the bounded priority queue of Paul
//! 2007 used by DynamO): time is cut into buckets of equal width, a ring of
//! them covers the near future, and each bucket is a doubly linked list of
//! the discs whose events fall in it. Setting an event unlinks the disc from
//! one list and links it into another, in O(1) whatever n; the earliest
//! event is the earliest in the first non-empty bucket, found by walking
//! forward from the current bucket. Events past the ring wait in an
//! overflow list, moved into the ring whenever the current bucket has gone
//! half-way round. The width is chosen from the events queued (about two
//! per bucket near the front) and chosen again when that drifts.
//!
//! Order is by time, then owner, exactly as a heap would give, so results
//! do not depend on the bucket width.

/// An event owned by one disc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Event<K> {
    /// When it happens (s from the start of the step).
    pub time: f64,
    /// The disc that predicted it.
    pub owner: u32,
    /// What happens.
    pub kind: K,
}

/// No disc: what [`EventQueue::soon`] and [`EventQueue::next_of`] give at
/// the end of a list.
pub(super) const NIL: u32 = u32::MAX;
/// The disc's event waits in the overflow list.
const OVERFLOW: u32 = u32::MAX - 1;
/// Events per bucket aimed at, near the front of the queue.
const PER_BUCKET: f64 = 2.0;
/// Ring buckets per disc (rounded up to a power of two).
const BUCKETS_PER_DISC: usize = 2;

/// A disc's event.
#[derive(Clone, Copy, Debug)]
struct Node<K> {
    time: f64,
    /// Ring slot, [`OVERFLOW`], or [`NIL`] when it has no event.
    bucket: u32,
    kind: Option<K>,
}

impl<K> Node<K> {
    const FREE: Node<K> = Node {
        time: f64::INFINITY,
        bucket: NIL,
        kind: None,
    };
}

/// Calendar queue of at most one event per disc.
///
/// The lists are linked through `next` and `prev`, which number every place
/// a list can pass through: the discs `0..n`, then the place past every
/// list's end (`n`, whose `prev` is scratch), then one head per ring slot
/// and one for the overflow (`n + 1 + slot`, `n + 1 + slots`; only `next`
/// has them). So a disc's predecessor is a disc or a head alike, and its
/// successor a disc or the end: linking and unlinking write without asking
/// which (these were a coin toss the processor guessed wrong about once per
/// event).
pub(super) struct EventQueue<K> {
    nodes: Vec<Node<K>>,
    next: Vec<u32>,
    prev: Vec<u32>,
    /// Discs in the ring, and in all.
    in_ring: usize,
    len: usize,
    /// Buckets per unit of time.
    per_second: f64,
    /// Added to every time before bucketing, so that shifting the clock's
    /// zero (between steps) moves no event.
    offset: f64,
    /// The bucket being looked at (absolute number); no event lies before it.
    cursor: u64,
    /// The ring covers buckets `base .. base + ring size`.
    base: u64,
    /// Ring slots (a power of two).
    slots: u64,
}

impl<K: Copy> EventQueue<K> {
    /// An empty queue for `n` discs.
    pub fn new(n: usize) -> Self {
        let slots = (BUCKETS_PER_DISC * n).next_power_of_two().max(16);
        let places = n + 1 + slots + 1;
        assert!(places < OVERFLOW as usize, "too many discs for the queue");
        let end = n as u32;
        EventQueue {
            nodes: vec![Node::FREE; n],
            next: vec![end; places],
            prev: vec![end; n + 1],
            in_ring: 0,
            len: 0,
            per_second: 1.0,
            offset: 0.0,
            cursor: 0,
            base: 0,
            slots: slots as u64,
        }
    }

    /// The place past every list's end.
    #[inline]
    fn end(&self) -> u32 {
        self.nodes.len() as u32
    }

    /// The head of ring slot `bucket`, or of the overflow ([`OVERFLOW`]).
    #[inline]
    fn head(&self, bucket: u32) -> usize {
        let first_head = self.nodes.len() + 1;
        if bucket == OVERFLOW {
            first_head + self.slots as usize
        } else {
            first_head + bucket as usize
        }
    }

    /// The absolute bucket of time `t`, never before the cursor.
    #[inline]
    fn bucket_number(&self, t: f64) -> u64 {
        let b = (t + self.offset) * self.per_second;
        if b.is_nan() || b <= self.cursor as f64 {
            self.cursor
        } else if b >= 9e18 {
            u64::MAX
        } else {
            // Positive and below 2⁶³, so the cast is the floor. Through i64
            // it is one instruction on x86-64 without AVX-512; u64's took
            // fifteen here (callgrind).
            b as i64 as u64
        }
    }

    /// Sets disc `owner`'s event (replacing any), or clears it with `None`.
    pub fn set(&mut self, owner: u32, event: Option<Event<K>>) {
        self.unlink(owner);
        if let Some(e) = event {
            self.link(owner, e.time, e.kind);
        }
    }

    fn link(&mut self, owner: u32, time: f64, kind: K) {
        let number = self.bucket_number(time);
        let bucket = if number - self.base < self.slots {
            self.in_ring += 1;
            (number & (self.slots - 1)) as u32
        } else {
            OVERFLOW
        };
        let head = self.head(bucket);
        let first = self.next[head];
        self.next[owner as usize] = first;
        self.prev[owner as usize] = head as u32;
        self.prev[first as usize] = owner; // scratch when `first` is the end
        self.next[head] = owner;
        self.nodes[owner as usize] = Node {
            time,
            bucket,
            kind: Some(kind),
        };
        self.len += 1;
    }

    fn unlink(&mut self, owner: u32) {
        let o = owner as usize;
        let bucket = self.nodes[o].bucket;
        if bucket == NIL {
            return;
        }
        let (next, prev) = (self.next[o], self.prev[o]);
        self.next[prev as usize] = next;
        self.prev[next as usize] = prev;
        if bucket != OVERFLOW {
            self.in_ring -= 1;
        }
        self.len -= 1;
        self.nodes[o] = Node::FREE;
    }

    /// The earliest of the list after `head` (by time, then owner).
    fn earliest_in(&self, head: usize) -> Option<u32> {
        let end = self.end();
        // Every disc is numbered below the end, so the first one beats it.
        let (mut best, mut best_time) = (end, f64::INFINITY);
        let mut k = self.next[head];
        while k != end {
            let time = self.nodes[k as usize].time;
            // Chosen without a branch: which one is earlier is a coin toss.
            let earlier = time < best_time || (time == best_time && k < best) || best == end;
            best = if earlier { k } else { best };
            best_time = if earlier { time } else { best_time };
            k = self.next[k as usize];
        }
        (best != end).then_some(best)
    }

    /// The owner of the earliest event; moves the cursor to its bucket.
    fn front(&mut self) -> Option<u32> {
        if self.len == 0 {
            return None;
        }
        loop {
            if self.in_ring == 0 {
                // Only far events: jump to the earliest and refill the ring.
                let first = self.earliest_in(self.head(OVERFLOW))?;
                let t = self.nodes[first as usize].time;
                let b = ((t + self.offset) * self.per_second).floor();
                self.cursor = if b.is_finite() && b > self.cursor as f64 {
                    (b as u64).min(u64::MAX / 2)
                } else {
                    self.cursor
                };
                self.refill();
                continue;
            }
            if self.cursor - self.base >= self.slots / 2 {
                self.refill();
            }
            let slot = (self.cursor & (self.slots - 1)) as u32;
            if let Some(k) = self.earliest_in(self.head(slot)) {
                return Some(k);
            }
            self.cursor += 1;
        }
    }

    /// Moves the ring's start to the cursor and the overflow events that
    /// now fall within it into it; chooses the width again first if the
    /// events have drifted away from it.
    fn refill(&mut self) {
        self.base = self.cursor;
        let (head, end) = (self.head(OVERFLOW), self.end());
        let mut k = self.next[head];
        self.next[head] = end;
        let mut moved = Vec::new();
        while k != end {
            let node = self.nodes[k as usize];
            moved.push((k, node.time, node.kind));
            k = self.next[k as usize];
        }
        if moved.len() > self.len / 4 {
            // Their nodes still say so: the retune finds them.
            return self.retune();
        }
        for (owner, time, kind) in moved {
            self.nodes[owner as usize] = Node::FREE;
            self.len -= 1;
            if let Some(kind) = kind {
                self.link(owner, time, kind);
            }
        }
    }

    /// Chooses the bucket width from the queued events (about
    /// [`PER_BUCKET`] events per bucket at the front) and re-buckets them.
    pub fn retune(&mut self) {
        let queued: Vec<(u32, f64, K)> = self
            .nodes
            .iter()
            .enumerate()
            .filter(|(_, node)| node.bucket != NIL)
            .filter_map(|(k, node)| Some((k as u32, node.time, node.kind?)))
            .collect();
        self.empty_lists();
        let mut times: Vec<f64> = queued.iter().map(|&(_, t, _)| t).collect();
        if let Some(&lo) = times.iter().min_by(|a, b| a.total_cmp(b)) {
            // The earliest event opens the ring (bucket 0), whatever the
            // width, so the ring is never empty after a retune.
            self.offset = -lo;
        }
        if times.len() >= 2 {
            // The earliest quarter of the events spans this much time.
            let quarter = (times.len() / 4).max(1);
            let (_, &mut q, _) = times.select_nth_unstable_by(quarter, f64::total_cmp);
            let span = q + self.offset;
            if span > 0.0 && span.is_finite() {
                self.per_second = quarter as f64 / (PER_BUCKET * span);
            }
        }
        self.cursor = 0;
        self.base = 0;
        for (owner, time, kind) in queued {
            self.link(owner, time, kind);
        }
    }

    /// Every list empty, no disc queued.
    fn empty_lists(&mut self) {
        let end = self.end();
        self.nodes.fill(Node::FREE);
        self.next.fill(end);
        self.prev.fill(end);
        self.in_ring = 0;
        self.len = 0;
    }

    /// A place in the lists as a disc, [`NIL`] for a head or the end.
    #[inline]
    fn disc(&self, k: u32) -> u32 {
        if (k as usize) < self.nodes.len() {
            k
        } else {
            NIL
        }
    }

    /// The first disc in the bucket `ahead` buckets past the current one
    /// ([`NIL`] if it is empty), whose event is likely to come soon.
    #[inline]
    pub fn soon(&self, ahead: u64) -> u32 {
        let slot = ((self.cursor + ahead) & (self.slots - 1)) as u32;
        self.disc(self.next[self.head(slot)])
    }

    /// The disc after `k` in its bucket's list ([`NIL`] at the end).
    #[inline]
    pub fn next_of(&self, k: u32) -> u32 {
        self.disc(self.next[k as usize])
    }

    /// Prefetches disc `k`'s event and links.
    #[inline]
    pub fn prefetch(&self, k: u32) {
        let k = k as usize;
        crate::parallel::prefetch(&self.nodes[k]);
        crate::parallel::prefetch(&self.next[k]);
        crate::parallel::prefetch(&self.prev[k]);
    }

    /// What disc `k`'s event is, if it has one.
    #[inline]
    pub fn kind_of(&self, k: u32) -> Option<K> {
        self.nodes[k as usize].kind
    }

    /// The earliest event, left in the queue.
    pub fn peek(&mut self) -> Option<Event<K>> {
        let k = self.front()?;
        let node = &self.nodes[k as usize];
        Some(Event {
            time: node.time,
            owner: k,
            kind: node.kind?,
        })
    }

    /// Whether an event other than the earliest (`top`'s) comes at or
    /// before `t`, a time in the current bucket.
    pub fn another_by(&self, top: u32, t: f64) -> bool {
        let slot = (self.cursor & (self.slots - 1)) as u32;
        let end = self.end();
        let mut k = self.next[self.head(slot)];
        while k != end {
            if k != top && self.nodes[k as usize].time <= t {
                return true;
            }
            k = self.next[k as usize];
        }
        false
    }

    /// Moves the clock's zero to `shift`: every time drops by it. Buckets
    /// stay as they are (the offset takes the shift).
    pub fn shift_times(&mut self, shift: f64) {
        let mut moved = 0;
        for node in &mut self.nodes {
            if node.bucket != NIL {
                node.time -= shift;
                moved += 1;
            }
        }
        debug_assert_eq!(moved, self.len);
        self.offset += shift;
    }

    /// The earliest event, removed from the queue.
    #[cfg(test)]
    pub fn pop(&mut self) -> Option<Event<K>> {
        let event = self.peek()?;
        self.set(event.owner, None);
        Some(event)
    }

    /// Empties the queue.
    pub fn clear(&mut self) {
        self.empty_lists();
        self.cursor = 0;
        self.base = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(time: f64, owner: u32) -> Option<Event<()>> {
        Some(Event {
            time,
            owner,
            kind: (),
        })
    }

    #[test]
    fn pops_in_time_order_with_replacements_and_removals() {
        let mut q = EventQueue::new(6);
        for (owner, time) in [(0, 5.0), (1, 3.0), (2, 4.0), (3, 1.0), (4, 2.0), (5, 6.0)] {
            q.set(owner, ev(time, owner));
        }
        q.set(3, ev(4.5, 3)); // later now
        q.set(5, ev(0.5, 5)); // earlier now
        q.set(2, None); // gone
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).map(|e| e.owner).collect();
        assert_eq!(order, vec![5, 4, 1, 3, 0]);
        assert!(q.pop().is_none());
    }

    #[test]
    fn a_thousand_random_updates_pop_sorted_whatever_the_width() {
        let n = 1000u32;
        for retune in [false, true] {
            let mut q = EventQueue::new(n as usize);
            let time = |k: u32| f64::from((k * 7919) % 1009);
            for k in 0..n {
                q.set(k, ev(time(k), k));
            }
            if retune {
                q.retune();
            }
            for k in (0..n).step_by(3) {
                q.set(k, ev(time(k) * 0.5 + 3.0, k));
            }
            for k in (0..n).step_by(7) {
                q.set(k, None);
            }
            let popped: Vec<(f64, u32)> = std::iter::from_fn(|| q.pop())
                .map(|e| (e.time, e.owner))
                .collect();
            assert_eq!(popped.len(), (0..n).filter(|k| k % 7 != 0).count());
            assert!(popped
                .windows(2)
                .all(|w| (w[0].0, w[0].1) <= (w[1].0, w[1].1)));
        }
    }

    #[test]
    fn interleaved_pops_and_pushes_keep_order_across_far_times_and_shifts() {
        // Like the method: take the earliest, re-queue its owner later
        // (sometimes much later, into the overflow), now and then shift the
        // clock's zero, and check that times never go backwards.
        let n = 500u32;
        let mut q = EventQueue::new(n as usize);
        let mut x: u64 = 12345;
        let mut rand = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % 1_000_000) as f64 / 1_000_000.0
        };
        for k in 0..n {
            q.set(k, ev(rand(), k));
        }
        q.retune();
        let mut last = f64::NEG_INFINITY;
        for step in 0..20_000 {
            let Some(e) = q.peek() else { break };
            assert!(e.time >= last, "step {step}: {} after {last}", e.time);
            last = e.time;
            let later = if step % 97 == 0 { 1e3 * rand() } else { rand() };
            q.set(e.owner, ev(e.time + later, e.owner));
            if step % 1000 == 999 {
                q.shift_times(e.time);
                last -= e.time;
            }
        }
    }

    #[test]
    fn a_lone_event_far_ahead_is_found() {
        // One slow disc: its only event lies far past the ring, and no
        // second event gives the width (this once looped for ever).
        for time in [100.0, 1e6, 1e12] {
            let mut q = EventQueue::new(1);
            q.set(0, ev(time, 0));
            q.retune();
            assert_eq!(q.pop().map(|e| e.time), Some(time));
            let mut q = EventQueue::new(3);
            q.set(0, ev(time, 0));
            assert_eq!(q.peek().map(|e| e.time), Some(time), "without a retune");
        }
    }

    #[test]
    fn ties_break_by_owner() {
        let mut q = EventQueue::new(3);
        for owner in [2, 0, 1] {
            q.set(owner, ev(1.0, owner));
        }
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).map(|e| e.owner).collect();
        assert_eq!(order, vec![0, 1, 2]);
    }

    #[test]
    fn another_event_by_the_front_s_time_is_found_as_a_search_of_all_would() {
        // Times on a coarse grid, so that ties are common.
        let n = 300u32;
        let mut q = EventQueue::new(n as usize);
        let mut times = vec![f64::INFINITY; n as usize];
        let mut x: u64 = 99;
        let mut rand = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for k in 0..n {
            times[k as usize] = (rand() % 50) as f64 * 0.25;
            q.set(k, ev(times[k as usize], k));
        }
        q.retune();
        for step in 0..5_000 {
            let Some(e) = q.peek() else { break };
            let others = (0..n).any(|k| k != e.owner && times[k as usize] <= e.time);
            assert_eq!(q.another_by(e.owner, e.time), others, "step {step}");
            // Sometimes another disc's event changes before the question.
            if step % 3 == 0 {
                let k = (rand() % u64::from(n)) as u32;
                times[k as usize] = e.time + (rand() % 3) as f64 * 0.25;
                q.set(k, ev(times[k as usize], k));
                let others = (0..n).any(|k| k != e.owner && times[k as usize] <= e.time);
                let top = q.peek().map(|t| t.owner);
                if top == Some(e.owner) {
                    assert_eq!(
                        q.another_by(e.owner, e.time),
                        others,
                        "step {step}, after a set"
                    );
                }
            }
            let owner = q.peek().unwrap().owner;
            times[owner as usize] += 0.25 * (1 + rand() % 8) as f64;
            q.set(owner, ev(times[owner as usize], owner));
        }
    }

    #[test]
    fn another_event_at_the_same_instant_is_seen() {
        let mut q = EventQueue::new(3);
        q.set(0, ev(1.0, 0));
        q.set(1, ev(1.0, 1));
        q.set(2, ev(2.0, 2));
        let top = q.peek().map(|e| e.owner);
        assert_eq!(top, Some(0));
        assert!(q.another_by(0, 1.0));
        q.set(1, ev(1.5, 1));
        assert!(!q.another_by(0, 1.0));
    }
}
