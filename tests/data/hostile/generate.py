#!/usr/bin/env python3
# Writes the hostile inputs of tests/hardening_cli_test.cpp (run it in this folder; the output is
# committed). Each file is small and declares more than it holds, or holds what no algorithm can
# use; the comment beside each says what the reader must refuse.
import struct
import zlib


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png(name, width, height, bit_depth, rows):
    """A greyscale PNG; `rows` is the raw scanline data (filter bytes included), or None for none."""
    header = struct.pack(">IIBBBBB", width, height, bit_depth, 0, 0, 0, 0)
    idat = zlib.compress(rows, 9) if rows is not None else zlib.compress(b"\0")
    with open(name, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) + png_chunk(b"IDAT", idat) + png_chunk(b"IEND", b""))


def tiff(name, width, height, strip_offset, strip_bytes, extra=()):
    """A little-endian float32 TIFF of one strip; `extra` adds (tag, type, count, payload) entries."""
    entries = [(256, 4, 1, struct.pack("<I", width)), (257, 4, 1, struct.pack("<I", height)),
               (258, 3, 1, struct.pack("<HH", 32, 0)), (259, 3, 1, struct.pack("<HH", 1, 0)),
               (262, 3, 1, struct.pack("<HH", 1, 0)), (273, 4, 1, struct.pack("<I", strip_offset)),
               (277, 3, 1, struct.pack("<HH", 1, 0)), (278, 4, 1, struct.pack("<I", height)),
               (279, 4, 1, struct.pack("<I", strip_bytes)), (339, 3, 1, struct.pack("<HH", 3, 0))]
    entries += list(extra)
    entries.sort()
    pixels = b"\0" * (width * height * 4 if width * height <= 64 else 16)
    ifd_offset = 8 + len(pixels)
    out_of_line = b""
    ifd_size = 2 + 12 * len(entries) + 4
    records = b""
    for tag, kind, count, payload in entries:
        if len(payload) <= 4:
            records += struct.pack("<HHI", tag, kind, count) + payload.ljust(4, b"\0")
        else:
            records += struct.pack("<HHII", tag, kind, count, ifd_offset + ifd_size + len(out_of_line))
            out_of_line += payload
    with open(name, "wb") as out:
        out.write(b"II*\0" + struct.pack("<I", ifd_offset) + pixels + struct.pack("<H", len(entries)) + records
                  + struct.pack("<I", 0) + out_of_line)


# 150 bytes declaring 37000² float pixels: its one strip runs past the end of the file.
tiff("declares_37000.tif", 37000, 37000, 8, 37000 * 37000 * 4 & 0xFFFFFFFF)
# A sound 4x4 GeoTIFF whose ModelPixelScale is 0: no slope can be computed on it.
tiff("zero_cell_size.tif", 4, 4, 8, 64, [(33550, 12, 3, struct.pack("<3d", 0.0, 0.0, 0.0))])
# A PNG header of 30000² 16-bit pixels and almost no data: diff-image must weigh the memory first.
png("declares_30000.png", 30000, 30000, 16, None)
# A real 8000² 8-bit PNG (64 MB of pixels, 62 KB compressed): readable, but pipe erosion needs
# about 3.5 KB a cell on it.
png("flat_8000.png", 8000, 8000, 8, b"\0" * (8000 * 8001))
