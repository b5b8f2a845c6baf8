#!/usr/bin/env python3
"""Prints the fraction of pixels that differ between two binary PPM images
of the same size (netpbm's P6), over the whole image or over the rectangle
x0 y0 x1 y1 (x1, y1 exclusive). Used by the viewer's tests."""
import sys


def read_ppm(path):
    data = open(path, "rb").read()
    fields, i = [], 0
    while len(fields) < 4:  # P6, width, height, maxval
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(data[i:j])
        i = j
    if fields[0] != b"P6":
        sys.exit(f"{path}: not a binary PPM")
    return int(fields[1]), int(fields[2]), data[i + 1:]


def main():
    w, h, a = read_ppm(sys.argv[1])
    w2, h2, b = read_ppm(sys.argv[2])
    if (w, h) != (w2, h2):
        sys.exit(f"sizes differ: {w}x{h} and {w2}x{h2}")
    x0, y0, x1, y1 = (int(v) for v in sys.argv[3:7]) if len(sys.argv) >= 7 else (0, 0, w, h)
    region = [(x, y) for y in range(y0, y1) for x in range(x0, x1)]
    changed = sum(1 for x, y in region
                  if a[3 * (y * w + x):3 * (y * w + x) + 3] != b[3 * (y * w + x):3 * (y * w + x) + 3])
    print(f"{changed / len(region):.4f}")


main()
