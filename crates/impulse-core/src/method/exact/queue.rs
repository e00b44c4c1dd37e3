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

/// End of a list, or no list.
pub(super) const NIL: u32 = u32::MAX;
/// The disc's event waits in the overflow list.
const OVERFLOW: u32 = u32::MAX - 1;
/// Events per bucket aimed at, near the front of the queue.
const PER_BUCKET: f64 = 2.0;
/// Ring buckets per disc (rounded up to a power of two).
const BUCKETS_PER_DISC: usize = 2;

/// A disc's event and its place in the queue, together so that one memory
/// access finds both.
#[derive(Clone, Copy, Debug)]
struct Node<K> {
    time: f64,
    next: u32,
    prev: u32,
    /// Ring slot, [`OVERFLOW`], or [`NIL`] when it has no event.
    bucket: u32,
    kind: Option<K>,
}

impl<K> Node<K> {
    const FREE: Node<K> = Node {
        time: f64::INFINITY,
        next: NIL,
        prev: NIL,
        bucket: NIL,
        kind: None,
    };
}

/// Calendar queue of at most one event per disc.
pub(super) struct EventQueue<K> {
    nodes: Vec<Node<K>>,
    /// First disc of each ring slot's list.
    heads: Vec<u32>,
    /// First disc of the overflow list.
    overflow: u32,
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
}

impl<K: Copy> EventQueue<K> {
    /// An empty queue for `n` discs.
    pub fn new(n: usize) -> Self {
        let slots = (BUCKETS_PER_DISC * n).next_power_of_two().max(16);
        EventQueue {
            nodes: vec![Node::FREE; n],
            heads: vec![NIL; slots],
            overflow: NIL,
            in_ring: 0,
            len: 0,
            per_second: 1.0,
            offset: 0.0,
            cursor: 0,
            base: 0,
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

    #[inline]
    fn ring_size(&self) -> u64 {
        self.heads.len() as u64
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
        let bucket = if number - self.base < self.ring_size() {
            self.in_ring += 1;
            (number & (self.ring_size() - 1)) as u32
        } else {
            OVERFLOW
        };
        let head = if bucket == OVERFLOW {
            &mut self.overflow
        } else {
            &mut self.heads[bucket as usize]
        };
        let next = *head;
        *head = owner;
        if next != NIL {
            self.nodes[next as usize].prev = owner;
        }
        self.nodes[owner as usize] = Node {
            time,
            next,
            prev: NIL,
            bucket,
            kind: Some(kind),
        };
        self.len += 1;
    }

    fn unlink(&mut self, owner: u32) {
        let node = self.nodes[owner as usize];
        if node.bucket == NIL {
            return;
        }
        if node.prev != NIL {
            self.nodes[node.prev as usize].next = node.next;
        } else if node.bucket == OVERFLOW {
            self.overflow = node.next;
        } else {
            self.heads[node.bucket as usize] = node.next;
        }
        if node.next != NIL {
            self.nodes[node.next as usize].prev = node.prev;
        }
        if node.bucket != OVERFLOW {
            self.in_ring -= 1;
        }
        self.len -= 1;
        self.nodes[owner as usize] = Node::FREE;
    }

    /// The earliest of the list starting at `first` (by time, then owner).
    fn earliest_in(&self, first: u32) -> Option<u32> {
        let mut best: Option<(f64, u32)> = None;
        let mut k = first;
        while k != NIL {
            let node = &self.nodes[k as usize];
            if best.is_none_or(|b| (node.time, k) < b) {
                best = Some((node.time, k));
            }
            k = node.next;
        }
        best.map(|(_, k)| k)
    }

    /// The owner of the earliest event; moves the cursor to its bucket.
    fn front(&mut self) -> Option<u32> {
        if self.len == 0 {
            return None;
        }
        loop {
            if self.in_ring == 0 {
                // Only far events: jump to the earliest and refill the ring.
                let first = self.earliest_in(self.overflow)?;
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
            if self.cursor - self.base >= self.ring_size() / 2 {
                self.refill();
            }
            let slot = (self.cursor & (self.ring_size() - 1)) as usize;
            if let Some(k) = self.earliest_in(self.heads[slot]) {
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
        let mut k = self.overflow;
        self.overflow = NIL;
        let mut moved = Vec::new();
        while k != NIL {
            let node = self.nodes[k as usize];
            moved.push((k, node.time, node.kind));
            k = node.next;
        }
        if moved.len() > self.len / 4 {
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
        self.heads.fill(NIL);
        self.nodes.fill(Node::FREE);
        self.overflow = NIL;
        self.in_ring = 0;
        self.len = 0;
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

    /// The first disc in the bucket `ahead` buckets past the current one
    /// ([`NIL`] if it is empty), whose event is likely to come soon.
    #[inline]
    pub fn soon(&self, ahead: u64) -> u32 {
        self.heads[((self.cursor + ahead) & (self.ring_size() - 1)) as usize]
    }

    /// The disc after `k` in its bucket's list ([`NIL`] at the end).
    #[inline]
    pub fn next_of(&self, k: u32) -> u32 {
        self.nodes[k as usize].next
    }

    /// Disc `k`'s queue node, for prefetching it.
    #[inline]
    pub fn node_of(&self, k: u32) -> &impl Sized {
        &self.nodes[k as usize]
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
        let slot = (self.cursor & (self.ring_size() - 1)) as usize;
        let mut k = self.heads[slot];
        while k != NIL {
            let node = &self.nodes[k as usize];
            if k != top && node.time <= t {
                return true;
            }
            k = node.next;
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
        self.nodes.fill(Node::FREE);
        self.heads.fill(NIL);
        self.overflow = NIL;
        self.in_ring = 0;
        self.len = 0;
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
