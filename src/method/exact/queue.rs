//! The event queue: one slot per disc holding its earliest predicted event,
//! kept in a heap indexed by disc, so re-predicting a disc replaces its old
//! event instead of leaving a stale copy behind. The heap never holds more
//! than n entries; pop and update are O(log n). It is 4-ary: a node's four
//! children share one cache line, which halves the depth of a binary heap.

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

const ABSENT: u32 = u32::MAX;

/// Children per heap node.
const ARITY: usize = 4;

/// Indexed 4-ary min-heap of events, ordered by time then owner. The heap
/// keeps each entry's time beside its owner so comparisons stay in one array.
pub(super) struct EventQueue<K> {
    heap: Vec<(f64, u32)>,
    slot: Vec<u32>,
    events: Vec<Option<Event<K>>>,
}

impl<K: Copy> EventQueue<K> {
    /// An empty queue for `n` discs.
    pub fn new(n: usize) -> Self {
        EventQueue {
            heap: Vec::with_capacity(n),
            slot: vec![ABSENT; n],
            events: vec![None; n],
        }
    }

    /// Event times are finite (the method queues no other), so plain
    /// comparisons order them.
    #[inline]
    fn before(a: (f64, u32), b: (f64, u32)) -> bool {
        a.0 < b.0 || (a.0 == b.0 && a.1 < b.1)
    }

    /// Sets disc `owner`'s event (replacing any), or clears it with `None`.
    pub fn set(&mut self, owner: u32, event: Option<Event<K>>) {
        let o = owner as usize;
        self.events[o] = event;
        let at = self.slot[o];
        let time = event.map_or(f64::INFINITY, |e| e.time);
        match (at == ABSENT, event.is_some()) {
            (true, true) => {
                self.slot[o] = self.heap.len() as u32;
                self.heap.push((time, owner));
                self.sift_up(self.heap.len() - 1);
            }
            (false, true) => {
                let at = at as usize;
                self.heap[at].0 = time;
                self.sift_up(at);
                self.sift_down(self.slot[o] as usize);
            }
            (false, false) => self.remove_at(at as usize),
            (true, false) => {}
        }
    }

    /// The earliest event, left in the queue.
    pub fn peek(&self) -> Option<Event<K>> {
        let &(_, top) = self.heap.first()?;
        self.events[top as usize]
    }

    /// Moves the clock's zero to `shift`: every time drops by it. Rounding
    /// is monotonic, so time order is kept (two times can become equal,
    /// which only changes which of two simultaneous events goes first).
    pub fn shift_times(&mut self, shift: f64) {
        for entry in &mut self.heap {
            entry.0 -= shift;
        }
        for event in self.events.iter_mut().flatten() {
            event.time -= shift;
        }
    }

    /// The earliest event, removed from the queue.
    ///
    /// Bottom-up: the hole left at the root moves down along the smallest
    /// children to a leaf, and the last entry is sifted up from there, which
    /// takes about half the comparisons of sifting the last entry down.
    pub fn pop(&mut self) -> Option<Event<K>> {
        let &(_, top) = self.heap.first()?;
        let event = self.events[top as usize].take();
        self.slot[top as usize] = ABSENT;
        let last = self.heap.pop().expect("non-empty");
        let len = self.heap.len();
        if len == 0 {
            return event;
        }
        let mut hole = 0;
        loop {
            let first_child = ARITY * hole + 1;
            if first_child >= len {
                break;
            }
            let child = self.smallest_child(first_child, len);
            self.heap[hole] = self.heap[child];
            self.slot[self.heap[hole].1 as usize] = hole as u32;
            hole = child;
        }
        self.heap[hole] = last;
        self.slot[last.1 as usize] = hole as u32;
        self.sift_up(hole);
        event
    }

    /// Empties the queue.
    pub fn clear(&mut self) {
        for &(_, owner) in &self.heap {
            self.slot[owner as usize] = ABSENT;
            self.events[owner as usize] = None;
        }
        self.heap.clear();
    }

    fn remove_at(&mut self, at: usize) {
        let (_, owner) = self.heap[at];
        self.slot[owner as usize] = ABSENT;
        let last = self.heap.pop();
        if let Some(last) = last {
            if at < self.heap.len() {
                self.heap[at] = last;
                self.slot[last.1 as usize] = at as u32;
                self.sift_up(at);
                self.sift_down(self.slot[last.1 as usize] as usize);
            }
        }
    }

    /// The earliest of the up to `ARITY` children starting at `first`.
    #[inline]
    fn smallest_child(&self, first: usize, len: usize) -> usize {
        let end = (first + ARITY).min(len);
        let mut best = first;
        let mut best_key = self.heap[first];
        for c in first + 1..end {
            let key = self.heap[c];
            if Self::before(key, best_key) {
                best = c;
                best_key = key;
            }
        }
        best
    }

    fn swap(&mut self, a: usize, b: usize) {
        self.heap.swap(a, b);
        self.slot[self.heap[a].1 as usize] = a as u32;
        self.slot[self.heap[b].1 as usize] = b as u32;
    }

    fn sift_up(&mut self, mut at: usize) {
        while at > 0 {
            let parent = (at - 1) / ARITY;
            if Self::before(self.heap[at], self.heap[parent]) {
                self.swap(at, parent);
                at = parent;
            } else {
                break;
            }
        }
    }

    fn sift_down(&mut self, mut at: usize) {
        let len = self.heap.len();
        loop {
            let first_child = ARITY * at + 1;
            if first_child >= len {
                break;
            }
            let child = self.smallest_child(first_child, len);
            if !Self::before(self.heap[child], self.heap[at]) {
                break;
            }
            self.swap(at, child);
            at = child;
        }
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
    fn a_thousand_random_updates_pop_sorted() {
        let n = 1000u32;
        let mut q = EventQueue::new(n as usize);
        let time = |k: u32| f64::from((k * 7919) % 1009);
        for k in 0..n {
            q.set(k, ev(time(k), k));
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

    #[test]
    fn ties_break_by_owner() {
        let mut q = EventQueue::new(3);
        for owner in [2, 0, 1] {
            q.set(owner, ev(1.0, owner));
        }
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).map(|e| e.owner).collect();
        assert_eq!(order, vec![0, 1, 2]);
    }
}
