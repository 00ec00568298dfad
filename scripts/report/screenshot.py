#!/usr/bin/env python3
"""Screenshots of a validation report as a browser shows it: headless Chromium (Debian package
`chromium`) renders DIR/index.html in one tall window, the empty space below the page is cut
off, and the page is written as OUT_full.png plus OUT_01.png, OUT_02.png, ... tiles of at most
--tile pixels height (small enough to look at).

usage: screenshot.py DIR OUT [--width 1280] [--height 30000] [--tile 2200] [--chromium chromium]
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("out")
    ap.add_argument("--width", type=int, default=1280)
    ap.add_argument("--height", type=int, default=30000, help="window height: at least the page's")
    ap.add_argument("--tile", type=int, default=2200)
    ap.add_argument("--chromium", default="chromium")
    a = ap.parse_args()
    page = os.path.join(os.path.abspath(a.dir), "index.html")
    if not os.path.isfile(page):
        print(f"screenshot.py: {page}: no report there", file=sys.stderr)
        return 2
    if not shutil.which(a.chromium):
        print(f"screenshot.py: {a.chromium}: not found (apt-get install chromium)", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        shot = os.path.join(tmp, "shot.png")
        cmd = [a.chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
               f"--user-data-dir={tmp}/profile", f"--window-size={a.width},{a.height}",
               "--virtual-time-budget=10000", f"--screenshot={shot}", "file://" + page]
        r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if r.returncode != 0 or not os.path.exists(shot):
            print(f"screenshot.py: chromium failed (exit {r.returncode}): {r.stderr.strip()[-300:]}", file=sys.stderr)
            return 1
        img = plt.imread(shot)[:, :, :3]
    # Cut the empty space below the page (rows equal to the last row).
    differs = np.any(np.abs(img - img[-1]) > 1e-3, axis=(1, 2))
    last = int(np.nonzero(differs)[0].max()) + 20 if differs.any() else img.shape[0]
    img = img[:min(last, img.shape[0])]
    if last >= a.height:
        print(f"screenshot.py: the page may be taller than --height {a.height}", file=sys.stderr)
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    plt.imsave(a.out + "_full.png", img)
    n = 0
    for y in range(0, img.shape[0], a.tile):
        n += 1
        plt.imsave(f"{a.out}_{n:02d}.png", img[y:y + a.tile])
    print(f"{a.out}_full.png: {img.shape[1]}x{img.shape[0]} px, {n} tiles {a.out}_01.png ...")
    return 0


if __name__ == "__main__":
    sys.exit(main())
