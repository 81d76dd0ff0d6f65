"""Progress of long calls (:func:`pressridge.simulate`, :func:`pressridge.campaign`).

``progress=True`` shows a bar: tqdm's (``tqdm.auto``: a widget in notebooks, a bar in
terminals) when tqdm is installed; otherwise one line on stderr, redrawn in place on a
terminal and written every few seconds elsewhere (a log, CI), like the command line's.
``progress=False`` (or None) is silent; a callable receives the raw numbers instead.
"""

import sys
import time
from typing import Any, Callable, Optional

#: Seconds between progress lines when stderr is not a terminal (as `--progress-interval`).
LOG_INTERVAL = 5.0


def _fmt(seconds: float) -> str:
    s = int(round(max(seconds, 0.0)))
    h, r = divmod(s, 3600)
    m, s = divmod(r, 60)
    return f"{h}h{m:02d}m{s:02d}s" if h else f"{m}m{s:02d}s" if m else f"{s}s"


class Bar:
    """A progress bar over ``total`` units (``unit`` names them) for ``desc``."""

    def __init__(self, total: float, desc: str, unit: str) -> None:
        self.total, self.desc, self.unit = float(total), desc, unit
        self.n = 0.0
        self.start = time.monotonic()
        self._last_line = -1e9
        self._tty = bool(getattr(sys.stderr, "isatty", lambda: False)())
        self._tqdm: Any = None
        try:
            from tqdm.auto import tqdm
        except ImportError:
            pass
        else:
            self._tqdm = tqdm(total=self.total, desc=desc, unit=unit)

    def update_to(self, n: float) -> None:
        """Moves the bar to ``n`` units done."""
        n = min(float(n), self.total)
        if self._tqdm is not None:
            self._tqdm.update(n - self.n)
            self.n = n
            return
        self.n = n
        now = time.monotonic()
        if not self._tty and now - self._last_line < LOG_INTERVAL and n < self.total:
            return
        self._last_line = now
        el = now - self.start
        frac = n / self.total if self.total > 0 else 1.0
        eta = el * (1.0 - frac) / frac if frac > 0 else float("nan")
        text = (
            f"{self.desc}: {n:.0f} of {self.total:.0f} {self.unit} ({100 * frac:.1f} %), "
            f"{_fmt(el)} elapsed" + (f", ETA {_fmt(eta)}" if frac < 1 and frac > 0 else "")
        )
        if self._tty:
            sys.stderr.write("\r" + text + ("\n" if n >= self.total else ""))
        else:
            sys.stderr.write(text + "\n")
        sys.stderr.flush()

    def close(self) -> None:
        """Ends the bar (a terminal line is finished)."""
        if self._tqdm is not None:
            self._tqdm.close()
        elif self._tty and self.n < self.total:
            sys.stderr.write("\n")
            sys.stderr.flush()


def callback(
    progress: Any, desc: str, unit: str, total: Optional[float] = None
) -> "tuple[Optional[Callable[..., None]], Optional[Bar]]":
    """Normalises a ``progress`` argument: (function to call, bar to close) or (None, None)
    for silence. A callable is returned as it is; True makes a :class:`Bar` (its total set
    at the first call when not known yet)."""
    if progress is None or progress is False:
        return None, None
    if callable(progress):
        return progress, None
    if progress is True:
        holder: dict = {}

        def show(done: float, total_now: float) -> None:
            bar = holder.get("bar")
            if bar is None:
                bar = holder["bar"] = Bar(total if total is not None else total_now, desc, unit)
            bar.update_to(done)

        class _Closer:
            def close(self) -> None:
                if "bar" in holder:
                    holder["bar"].close()

        return show, _Closer()  # type: ignore[return-value]
    raise ValueError(f"progress must be True, False or a callable; got {progress!r}")
