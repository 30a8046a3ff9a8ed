#!/usr/bin/env python3
"""Decides whether a PNG screenshot of the playground shows the scene or a blank frame.

    check_screenshot.py out.png                 exit 0 when it shows a scene, 1 when blank
    check_screenshot.py --expect-blank out.png  exit 0 when it is blank (the check's own test)

The PNG is decoded here (zlib and the five row filters, standard library only), independently of
the program that wrote it, so a broken writer fails too. A frame in which nothing but the clear
colour was drawn has one colour covering 100 % of it; the HUD over such a frame adds 2 or 3
colours. The lit room is shaded smoothly (per-vertex lighting across every wall, floor tile,
shape and skin), which gives thousands of colours, none covering more than a fraction of the
frame. So a frame is taken as showing the scene when it has at least MIN_COLOURS distinct
colours and no colour covers more than MAX_SHARE of it: two orders of magnitude from a blank
frame on the first count, and a blank frame's 100 % against 50 % on the second.
"""
import struct
import sys
import zlib

MIN_COLOURS = 200
MAX_SHARE = 0.5


def decode_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
            raise ValueError("bad CRC in chunk %r" % kind)
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
        pos += 12 + length
    if header is None:
        raise ValueError("no IHDR chunk")
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace != 0:
        raise ValueError("only 8-bit RGB or RGBA, non-interlaced, is read here")
    bpp = 3 if colour_type == 2 else 4
    raw, stride = zlib.decompress(idat), width * bpp
    if len(raw) != height * (stride + 1):
        raise ValueError("image data of %d bytes, %d expected" % (len(raw), height * (stride + 1)))
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - bpp] if i >= bpp else 0
            up, up_left = previous[i], previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + left) & 0xFF
            elif kind == 2:
                line[i] = (line[i] + up) & 0xFF
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 0xFF
            elif kind != 0:
                raise ValueError("unknown row filter %d" % kind)
        rows.append(bytes(line))
        previous = line
    return width, height, bpp, rows


def main(argv):
    expect_blank = "--expect-blank" in argv
    paths = [a for a in argv if a != "--expect-blank"]
    if len(paths) != 1:
        print(__doc__)
        return 2
    try:
        width, height, bpp, rows = decode_png(paths[0])
    except (OSError, ValueError, zlib.error) as e:
        print("check_screenshot: %s: %s" % (paths[0], e))
        return 2
    counts = {}
    for row in rows:
        for x in range(width):
            pixel = row[x * bpp:x * bpp + 3]
            counts[pixel] = counts.get(pixel, 0) + 1
    share = max(counts.values()) / float(width * height)
    shows_scene = len(counts) >= MIN_COLOURS and share <= MAX_SHARE
    print("check_screenshot: %s: %dx%d, %d distinct colours, the commonest covers %.1f %%: %s"
          % (paths[0], width, height, len(counts), 100 * share, "the scene" if shows_scene else "blank"))
    return 0 if shows_scene != expect_blank else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
