"""fill()'s `progress` argument: a callable, or True for a bar (tqdm when importable)."""

import sys


class _Bar:
    """A bar in percent of the area to fill, then of the jam stage's rounds (fill(jam=True)), then of the certification."""

    def __init__(self):
        try:
            from tqdm.auto import tqdm
        except ImportError:
            tqdm = None
        self._tqdm = tqdm(total=100, unit="%", desc="filling", leave=False) if tqdm else None
        self._phase = "generate"

    def __call__(self, p):
        percent = int(p.fraction * 100)
        if p.phase != self._phase:
            self._phase = p.phase
            if self._tqdm is not None:
                self._tqdm.reset(total=100)
                self._tqdm.set_description({"certify": "certifying", "jam": "jamming"}.get(p.phase, p.phase))
        if self._tqdm is not None:
            self._tqdm.update(percent - self._tqdm.n)
            self._tqdm.set_postfix(disks=p.disks, refresh=False)
        else:
            sys.stderr.write("\rfrontpack: %s %3d%% (%d disks)" % (p.phase, percent, p.disks))
            sys.stderr.flush()

    def close(self):
        if self._tqdm is not None:
            self._tqdm.close()
        else:
            sys.stderr.write("\n")


def callback(progress):
    """(the callable fill() passes to the library, a function to call once the run is over)."""
    if progress is None or progress is False:
        return None, lambda: None
    if progress is True:
        bar = _Bar()
        return bar, bar.close
    if callable(progress):
        return progress, lambda: None
    raise TypeError("progress must be a callable, True (a bar) or None")
