//! A small team of threads for the force phases of a step ([`crate::dem::World::set_threads`]).
//!
//! Each phase of a step (the outlines, the water forces, the joint law, the contact geometry)
//! is a few microseconds of work, about 1.6 million times in the default run. A rayon pool
//! lost to one thread there (`docs/notes/performance-simulator.md`, "Threads within a run"):
//! its idle workers yield and then sleep in the kernel, so each phase waited for a worker to
//! be woken. The team's workers instead spin on a counter while a run steps (a phase reaches
//! them in well under a microsecond) and park only after [`SPIN`] without work, so a paused
//! or finished run leaves its cores to others. That spinning is why this is hand-rolled: no
//! well-kept crate offers fork–join with a bounded busy wait.
//!
//! A phase is split into at most [`MAX_PARTS`] parts that the threads (the caller too) claim
//! one at a time; every part is computed on its own and written to its own place, and what is
//! summed is summed afterwards on the caller in a fixed order, so the bits do not depend on
//! the number of threads or on which thread took which part.

use std::cell::UnsafeCell;
use std::marker::PhantomData;
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering::SeqCst};
use std::sync::{Arc, Mutex};
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

/// How long an idle worker spins before it parks.
pub(crate) const SPIN: Duration = Duration::from_micros(500);

/// The most parts a phase is split into (the bits of [`Chunks`]' claim mask).
pub(crate) const MAX_PARTS: usize = 64;

/// One phase's work: `job(k)` computes part `k`.
type Job = dyn Fn(usize) + Sync;

/// What the caller and the workers share.
struct Shared {
    /// Bumped once per phase (and once to stop).
    epoch: AtomicU64,
    /// The phase's work; set by the caller before it bumps `epoch`, read by a worker after it
    /// has seen the bump. A raw pointer because the job borrows the caller's stack.
    job: UnsafeCell<*const Job>,
    /// Parts of the phase.
    parts: AtomicUsize,
    /// The next part to claim.
    next: AtomicUsize,
    /// Workers that have not yet finished the phase.
    pending: AtomicUsize,
    /// Per worker: parked, or about to park.
    sleeping: Vec<AtomicBool>,
    /// A part panicked on a worker; the caller re-raises it.
    panic: Mutex<Option<Box<dyn std::any::Any + Send>>>,
    /// The team is being dropped.
    stop: AtomicBool,
    /// A phase is running: a second caller (a cloned world on another thread) runs its own
    /// phase on itself instead of waiting.
    busy: AtomicBool,
}

// SAFETY: `job` is the only field that is not `Sync` by itself. The caller writes it only
// while no worker reads it: before it bumps `epoch` (a worker reads it only after seeing the
// bump, which orders the write before the read) and after every worker of the previous phase
// has decremented `pending` (after which no worker reads it until the next bump). The job it
// points to is `Sync`.
unsafe impl Sync for Shared {}
// SAFETY: the pointer in `job` is dereferenced only under the protocol above; the job is
// `Sync`, so using it from another thread is allowed.
unsafe impl Send for Shared {}

/// A team of `threads` threads (the caller and `threads − 1` workers).
pub(crate) struct Team {
    shared: Arc<Shared>,
    workers: Vec<JoinHandle<()>>,
}

impl std::fmt::Debug for Team {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Team({} threads)", self.threads())
    }
}

impl Team {
    /// Starts `threads − 1` workers (`threads` ≥ 2). An error when a thread cannot start.
    pub(crate) fn new(threads: usize) -> std::io::Result<Team> {
        let n = threads.saturating_sub(1);
        let noop: &Job = &|_| {};
        let shared = Arc::new(Shared {
            epoch: AtomicU64::new(0),
            job: UnsafeCell::new(noop as *const Job),
            parts: AtomicUsize::new(0),
            next: AtomicUsize::new(0),
            pending: AtomicUsize::new(0),
            sleeping: (0..n).map(|_| AtomicBool::new(false)).collect(),
            panic: Mutex::new(None),
            stop: AtomicBool::new(false),
            busy: AtomicBool::new(false),
        });
        let mut team = Team {
            shared: shared.clone(),
            workers: Vec::with_capacity(n),
        };
        for w in 0..n {
            let s = shared.clone();
            let handle = thread::Builder::new()
                .name(format!("pressridge-step-{}", w + 1))
                .spawn(move || work(&s, w))?;
            team.workers.push(handle);
        }
        Ok(team)
    }

    /// The number of threads, the caller included.
    pub(crate) fn threads(&self) -> usize {
        self.workers.len() + 1
    }

    /// Runs `job(k)` for every `k` in `0..parts` on the team's threads and the caller's, and
    /// returns when all are done. A panic in a part is raised again here.
    pub(crate) fn run(&self, parts: usize, job: &(dyn Fn(usize) + Sync)) {
        let s = &*self.shared;
        if parts <= 1 || s.busy.swap(true, SeqCst) {
            (0..parts).for_each(job);
            return;
        }
        // SAFETY: the lifetime of `job` is erased to store it; it is read by the workers only
        // until each has decremented `pending`, and this function waits for `pending` to reach
        // zero before it returns, while `job` is still borrowed. No worker reads `job` now
        // (the previous phase ended with `pending` at zero, and the next bump is below).
        unsafe {
            let erased: *const Job = std::mem::transmute::<&(dyn Fn(usize) + Sync), &Job>(job);
            *s.job.get() = erased;
        }
        s.parts.store(parts, SeqCst);
        s.next.store(0, SeqCst);
        s.pending.store(self.workers.len(), SeqCst);
        s.epoch.fetch_add(1, SeqCst);
        self.wake();
        // The caller's own parts may panic too: the workers must be done with `job` before
        // the panic leaves this function.
        let mine = catch_unwind(AssertUnwindSafe(|| claim(s, job)));
        while s.pending.load(SeqCst) != 0 {
            std::hint::spin_loop();
        }
        s.busy.store(false, SeqCst);
        let theirs = s.panic.lock().unwrap_or_else(|e| e.into_inner()).take();
        if let Some(p) = mine.err().or(theirs) {
            resume_unwind(p);
        }
    }

    /// Unparks the workers that are parked or about to park.
    fn wake(&self) {
        for (w, handle) in self.workers.iter().enumerate() {
            if self.shared.sleeping[w].load(SeqCst) {
                handle.thread().unpark();
            }
        }
    }
}

impl Drop for Team {
    fn drop(&mut self) {
        self.shared.stop.store(true, SeqCst);
        self.shared.epoch.fetch_add(1, SeqCst);
        for handle in &self.workers {
            handle.thread().unpark();
        }
        for handle in self.workers.drain(..) {
            let _ = handle.join();
        }
    }
}

/// Claims and runs parts of the phase until none is left.
fn claim(s: &Shared, job: &(dyn Fn(usize) + Sync)) {
    let parts = s.parts.load(SeqCst);
    loop {
        let k = s.next.fetch_add(1, SeqCst);
        if k >= parts {
            return;
        }
        job(k);
    }
}

/// A worker's loop: wait for a phase (spinning, then parked), take parts, report done.
fn work(s: &Shared, w: usize) {
    // The epoch the team was made with: a phase may be posted before this thread runs.
    let mut seen = 0;
    loop {
        let start = Instant::now();
        let mut spins = 0u32;
        while s.epoch.load(SeqCst) == seen {
            std::hint::spin_loop();
            spins = spins.wrapping_add(1);
            if spins % 256 == 0 && start.elapsed() > SPIN {
                // Announce the park, then look once more: the caller bumps the epoch before
                // it reads `sleeping`, so either this load sees the bump or the caller sees
                // the flag and unparks (an unpark before the park makes it return at once).
                s.sleeping[w].store(true, SeqCst);
                while s.epoch.load(SeqCst) == seen {
                    thread::park();
                }
                s.sleeping[w].store(false, SeqCst);
            }
        }
        // One bump at a time: the caller posts no phase before this worker has finished
        // the last one.
        seen += 1;
        if s.stop.load(SeqCst) {
            return;
        }
        // SAFETY: the epoch was bumped after the caller stored the job, and the caller waits
        // for this worker's decrement of `pending` below before the job goes out of scope.
        let job = unsafe { &**s.job.get() };
        if let Err(p) = catch_unwind(AssertUnwindSafe(|| claim(s, job))) {
            *s.panic.lock().unwrap_or_else(|e| e.into_inner()) = Some(p);
        }
        s.pending.fetch_sub(1, SeqCst);
    }
}

/// A slice split into consecutive chunks that the parts of a phase write, each chunk once:
/// [`Chunks::get`] hands out chunk `k` one time only (a second request panics), so the
/// chunks the threads hold never overlap.
pub(crate) struct Chunks<'a, T> {
    ptr: *mut T,
    len: usize,
    chunk: usize,
    taken: AtomicU64,
    _slice: PhantomData<&'a mut [T]>,
}

// SAFETY: the chunks handed out are disjoint (each index once, checked by `taken`), so
// threads holding them write different elements; `T: Send` lets the elements be written from
// another thread.
unsafe impl<T: Send> Sync for Chunks<'_, T> {}

impl<'a, T> Chunks<'a, T> {
    /// `slice` in `parts` chunks of equal length (the last shorter), `parts` ≤ [`MAX_PARTS`].
    pub(crate) fn new(slice: &'a mut [T], parts: usize) -> Chunks<'a, T> {
        assert!(parts <= MAX_PARTS, "at most {MAX_PARTS} parts");
        let len = slice.len();
        Chunks {
            ptr: slice.as_mut_ptr(),
            len,
            chunk: len.div_ceil(parts.max(1)).max(1),
            taken: AtomicU64::new(0),
            _slice: PhantomData,
        }
    }

    /// The index of the first element of chunk `k`.
    pub(crate) fn start(&self, k: usize) -> usize {
        (k * self.chunk).min(self.len)
    }

    /// Chunk `k` (empty past the end). Panics when chunk `k` was already handed out.
    #[allow(clippy::mut_from_ref)]
    pub(crate) fn get(&self, k: usize) -> &mut [T] {
        assert!(k < MAX_PARTS, "chunk {k} of at most {MAX_PARTS}");
        let bit = 1u64 << k;
        assert!(self.taken.fetch_or(bit, SeqCst) & bit == 0, "chunk {k} taken twice");
        let (a, b) = (self.start(k), self.start(k + 1));
        // SAFETY: `a..b` lies within the slice borrowed for 'a, and chunk `k` is handed out
        // once (the check above), so no other live reference covers these elements.
        unsafe { std::slice::from_raw_parts_mut(self.ptr.add(a), b - a) }
    }
}

/// The parts to split `len` items into on `threads` threads: four per thread (so that a
/// thread that finishes early takes another), at most [`MAX_PARTS`], at most one per item.
pub(crate) fn parts_for(len: usize, threads: usize) -> usize {
    (4 * threads).min(MAX_PARTS).min(len).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every element is written once, by whichever thread took its chunk, over many phases in
    /// a row (the spin hand-over) and after the workers have parked (the park hand-over).
    #[test]
    fn every_part_runs_once_on_any_number_of_threads() {
        for threads in [2, 3, 4] {
            let team = Team::new(threads).unwrap();
            assert_eq!(team.threads(), threads);
            for round in 0..2000usize {
                let mut v = vec![0usize; 1 + round % 300];
                let parts = parts_for(v.len(), threads);
                let chunks = Chunks::new(&mut v, parts);
                team.run(parts, &|k| {
                    let start = chunks.start(k);
                    for (i, x) in chunks.get(k).iter_mut().enumerate() {
                        *x += start + i + round;
                    }
                });
                assert!(v.iter().enumerate().all(|(i, &x)| x == i + round));
                if round % 500 == 0 {
                    thread::sleep(2 * SPIN);
                }
            }
        }
    }

    /// A chunk handed out twice is refused (the guarantee behind the disjoint writes).
    #[test]
    #[should_panic(expected = "taken twice")]
    fn a_chunk_is_handed_out_once() {
        let mut v = vec![0; 8];
        let chunks = Chunks::new(&mut v, 4);
        let _a = chunks.get(1);
        let _b = chunks.get(1);
    }

    /// A panic in a part on a worker reaches the caller, and the team works on after it.
    #[test]
    fn a_panic_in_a_part_reaches_the_caller() {
        let team = Team::new(2).unwrap();
        let r = catch_unwind(AssertUnwindSafe(|| {
            team.run(8, &|k| {
                if k == 7 {
                    panic!("part 7");
                }
            })
        }));
        assert!(r.is_err());
        let n = AtomicUsize::new(0);
        team.run(8, &|_| {
            n.fetch_add(1, SeqCst);
        });
        assert_eq!(n.load(SeqCst), 8);
    }
}
