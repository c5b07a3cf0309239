"""Progress display for long runs: tqdm when installed (Debian python3-tqdm), else a plain
line on stderr rewritten in place."""

import sys
import time


class Progress:
    """Shows the engine time going from t0 to t1."""

    def __init__(self, t0, t1, label):
        self.t0, self.t1 = t0, t1
        self.span = max(t1 - t0, 1e-300)
        self.start = time.monotonic()
        try:
            from tqdm import tqdm
            self.bar = tqdm(total=round(t1 - t0, 12), desc=label, unit="t", leave=True,
                            bar_format="{desc}: {percentage:3.0f}%|{bar}| t {n:.4g}/{total:.4g} "
                                       "[{elapsed}<{remaining}]")
        except ImportError:
            self.bar = None
            self.label = label

    def __call__(self, t):
        done = min(max(t - self.t0, 0.0), self.t1 - self.t0)
        if self.bar is not None:
            self.bar.n = round(done, 12)
            self.bar.refresh()
        else:
            f = done / self.span
            wall = time.monotonic() - self.start
            left = wall * (1.0 - f) / f if f > 0 else float("nan")
            sys.stderr.write(f"\r{self.label}: {100 * f:5.1f}%  t = {t:.6g} / {self.t1:.6g}"
                             f"  {wall:.0f} s, about {left:.0f} s left ")
            sys.stderr.flush()

    def close(self, t):
        self(t)
        if self.bar is not None:
            self.bar.close()
        else:
            sys.stderr.write("\n")
