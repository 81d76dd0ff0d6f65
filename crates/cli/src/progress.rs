//! Progress of long commands (`simulate`, `campaign`) on stderr: a bar on a terminal, and
//! when stderr is not a terminal (a log file, CI, a pipe) one line every
//! `--progress-interval` seconds with the elapsed time, the work done, the rate and an ETA.
//! Both show the same ETA, from [`pressridge::eta`]: `simulate` assumes the cost of a
//! simulated second grows linearly as the ridge grows, `campaign` a constant rate.
//! `--quiet` silences both; `-v` adds detail (steps, step size, runs).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pressridge::eta::{Eta, Model};
use std::io::IsTerminal;
use std::sync::Mutex;
use std::sync::OnceLock;
use std::time::{Duration, Instant};

/// The global options of progress reporting (set once from the command line).
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// No progress at all.
    pub quiet: bool,
    /// Verbosity (0 = normal; 1 and more add detail).
    pub verbose: u8,
    /// Seconds between progress lines when stderr is not a terminal.
    pub interval: f64,
}

static OPTIONS: OnceLock<Options> = OnceLock::new();

/// Sets the options; call once before any [`Progress`] is made.
pub fn configure(o: Options) {
    let _ = OPTIONS.set(o);
}

/// The options set by [`configure`] (defaults: not quiet, not verbose, 5 s).
pub fn options() -> Options {
    *OPTIONS.get_or_init(|| Options {
        quiet: false,
        verbose: 0,
        interval: 5.0,
    })
}

enum Kind {
    Quiet,
    Bar(ProgressBar),
    Lines,
}

/// Progress towards a total amount of work (`unit`: what is counted, e.g. "s simulated").
pub struct Progress {
    kind: Kind,
    start: Instant,
    total: f64,
    unit: &'static str,
    /// Seconds between lines (line mode).
    interval: Duration,
    /// When the last report was drawn.
    last: Mutex<Option<Instant>>,
    /// Work done before this process started (resumed campaigns): not in the rate.
    base: Mutex<Option<f64>>,
    /// The ETA estimator ([`pressridge::eta`]), fed at every report.
    eta: Mutex<Eta>,
}

/// `d` as `1h02m03s`, `2m03s` or `3s`.
pub fn hms(d: f64) -> String {
    if !d.is_finite() {
        return "?".into();
    }
    let s = d.max(0.0).round() as u64;
    let (h, m, s) = (s / 3600, (s / 60) % 60, s % 60);
    if h > 0 {
        format!("{h}h{m:02}m{s:02}s")
    } else if m > 0 {
        format!("{m}m{s:02}s")
    } else {
        format!("{s}s")
    }
}

impl Progress {
    /// A progress report towards `total` (in `unit`), drawn as the options and stderr say,
    /// its ETA estimated with `model` (see [`pressridge::eta`]).
    pub fn new(total: f64, unit: &'static str, model: Model) -> Progress {
        let o = options();
        let kind = if o.quiet {
            Kind::Quiet
        } else if std::io::stderr().is_terminal() {
            let bar = ProgressBar::with_draw_target(
                Some((total * 1000.0).round().max(1.0) as u64),
                ProgressDrawTarget::stderr(),
            );
            if let Ok(style) =
                ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:40} {msg}")
            {
                bar.set_style(style.progress_chars("=> "));
            }
            Kind::Bar(bar)
        } else {
            Kind::Lines
        };
        Progress {
            kind,
            start: Instant::now(),
            total,
            unit,
            interval: Duration::from_secs_f64(o.interval),
            last: Mutex::new(None),
            base: Mutex::new(None),
            eta: Mutex::new(Eta::new(total, model)),
        }
    }

    /// Reports `done` (in the unit) of the total. `text` gives the message in words and a
    /// detail shown with `-v` only; it is called only when something is drawn, so a caller
    /// may report every step.
    pub fn update(&self, done: f64, text: impl FnOnce() -> (String, String)) {
        self.report(done, 0.0, text);
    }

    /// As [`update`](Self::update), with the first call's `done` as work done before this
    /// process (a resumed campaign), left out of the rate and the ETA.
    pub fn update_resumed(&self, done: f64, text: impl FnOnce() -> (String, String)) {
        let base = *self.base.lock().expect("progress lock").get_or_insert(done);
        self.report(done, base, text);
    }

    fn report(&self, done: f64, base: f64, text: impl FnOnce() -> (String, String)) {
        let verbose = options().verbose > 0;
        let interval = match &self.kind {
            Kind::Quiet => return,
            Kind::Bar(_) => Duration::from_millis(100),
            Kind::Lines => self.interval,
        };
        let now = Instant::now();
        {
            let mut last = self.last.lock().expect("progress lock");
            let since = now.duration_since(last.unwrap_or(self.start));
            if since < interval {
                return;
            }
            *last = Some(now);
        }
        let (msg, detail) = text();
        let elapsed = now.duration_since(self.start).as_secs_f64();
        let eta = {
            let mut e = self.eta.lock().expect("progress lock");
            e.observe(elapsed, done);
            e.remaining().map_or_else(|| "?".into(), hms)
        };
        match &self.kind {
            Kind::Quiet => {}
            Kind::Bar(bar) => {
                bar.set_position((done * 1000.0).round().max(0.0) as u64);
                if verbose && !detail.is_empty() {
                    bar.set_message(format!("{msg}, {detail}, ETA {eta}"));
                } else {
                    bar.set_message(format!("{msg}, ETA {eta}"));
                }
            }
            Kind::Lines => {
                let rate = (done - base) / elapsed.max(1e-9);
                let pct = 100.0 * done / self.total.max(f64::MIN_POSITIVE);
                let mut line = format!(
                    "pressridge: {} elapsed, {msg} ({pct:.1} %), {rate:.3} {}/s, ETA {eta}",
                    hms(elapsed),
                    self.unit
                );
                if verbose && !detail.is_empty() {
                    line.push_str(", ");
                    line.push_str(&detail);
                }
                eprintln!("{line}");
            }
        }
    }

    /// Ends the report: clears the bar; in line mode prints nothing more.
    pub fn finish(&self) {
        if let Kind::Bar(bar) = &self.kind {
            bar.finish_and_clear();
        }
    }
}
