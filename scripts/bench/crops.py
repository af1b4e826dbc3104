#!/usr/bin/python3
"""A strip of crops of final images next to the reference's (convergence.sh, suite.sh).

Usage: crops.py FINALS_CSV REFERENCE_PNG OUT_PNG TITLE [CROP]
FINALS_CSV has columns configuration and png; TITLE may hold one %s for the crop's place and size;
CROP is "X Y W H" in pixels (default, or empty: the centre third).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def main(finals, ref_png, out_png, title, crop=""):
    rows = list(csv.DictReader(open(finals)))
    ref = mpimg.imread(ref_png)
    h, w = ref.shape[:2]
    x, y, cw, ch = map(int, crop.split()) if crop else (w // 3, h // 3, w // 3, h // 3)
    panels = [("reference", ref)] + [(r["configuration"], mpimg.imread(r["png"])) for r in rows]
    fig, axes = plt.subplots(1, len(panels), figsize=(2.2 * len(panels), 2.5))
    for ax, (name, img) in zip(axes, panels):
        ax.imshow(img[y:y + ch, x:x + cw], interpolation="nearest")
        ax.set_title(name, fontsize=9)
        ax.axis("off")
    place = "crop (%d, %d) %dx%d" % (x, y, cw, ch)
    fig.suptitle(title % place if "%s" in title else "%s: %s" % (title, place), fontsize=10)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:6])
