#!/usr/bin/env python3
"""Stand-in texture files for a library of effects whose own textures are not at hand.

    scripts/standin_textures.py TOOL LIBRARY_COPY EFFECT...

Public copies of effect libraries (NVIDIA's FX Composer library among them) often leave out the image
files their effects name, and an effect whose picture comes from its texture (digits, a dot screen, a
lookup table) then draws one flat shade with the neutral texture. To tell those effects from ones that
draw nothing for another reason, this script renders each EFFECT (relative to LIBRARY_COPY, which it
writes into: give it a copy) with `TOOL render EFFECT --scene teapot`, reads the warnings that name a
texture file it cannot load, and writes a file of that name beside the effect: a 64 x 64 colour gradient
under a checker, as a 2D texture, or a cube or volume texture where the next render says the effect
samples it as one. The file's format follows its extension: DDS (uncompressed A8R8G8B8), PNG, TGA, BMP or
Radiance HDR. A frame drawn with stand-ins shows what the effect does with *a* texture, not the picture
of the missing one: a lookup table's shape, a mip chain's levels, or a file format's conventions (an HDR
file read as raw RGBE bytes) are not reproduced.
"""
import math
import pathlib
import re
import struct
import subprocess
import sys
import tempfile
import zlib

SIZE = 64
VOLUME_SIZE = 16
MISSING = re.compile(r"cannot load texture '([^']+)'")
WRONG_KIND = re.compile(r"texture file '([^']+)' holds a \S+ texture, but the effect samples it as a (cube|volume)")


def texel(x, y, layer=0):
    """A gradient in red and green under an 8-texel checker in green and blue; each layer shifted."""
    check = ((x // 8 + y // 8) % 2) * 60
    return ((x * 255 // (SIZE - 1) + layer * 40) % 256, (y * 255 // (SIZE - 1) + check) % 256,
            (128 + layer * 20 + check) % 256, 255)


def dds(kind):
    size = VOLUME_SIZE if kind == "volume" else SIZE
    layers = {"cube": 6, "volume": VOLUME_SIZE}.get(kind, 1)
    flags = 0x1 | 0x2 | 0x4 | 0x8 | 0x1000 | (0x800000 if kind == "volume" else 0)
    caps = 0x1000 | (0x8 if kind != "2D" else 0)
    caps2 = {"cube": 0xFE00, "volume": 0x200000}.get(kind, 0)
    pixel_format = struct.pack("<8I", 32, 0x41, 0, 32, 0x00FF0000, 0x0000FF00, 0x000000FF, 0xFF000000)
    header = (struct.pack("<7I", 124, flags, size, size, size * 4, layers if kind == "volume" else 0, 1) +
              b"\0" * 44 + pixel_format + struct.pack("<5I", caps, caps2, 0, 0, 0))
    texels = bytearray()
    for layer in range(layers):
        for y in range(size):
            for x in range(size):
                r, g, b, a = texel(x * SIZE // size, y * SIZE // size, layer)
                texels += bytes((b, g, r, a))
    return b"DDS " + header + bytes(texels)


def png():
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    rows = b"".join(b"\0" + b"".join(bytes(texel(x, y)) for x in range(SIZE)) for y in range(SIZE))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def tga():
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, SIZE, SIZE, 32, 8)
    return header + b"".join(bytes((b, g, r, a)) for y in range(SIZE) for x in range(SIZE)
                             for r, g, b, a in [texel(x, y)])


def bmp():
    texels = b"".join(bytes((b, g, r)) for y in range(SIZE) for x in range(SIZE) for r, g, b, _ in [texel(x, y)])
    return (b"BM" + struct.pack("<IHHI", 54 + len(texels), 0, 0, 54) +
            struct.pack("<IiiHHIIiiII", 40, SIZE, SIZE, 1, 24, 0, len(texels), 2835, 2835, 0, 0) + texels)


def hdr():
    out = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (SIZE, SIZE))
    for y in range(SIZE):
        for x in range(SIZE):
            value = [c / 255 * 0.9 + 0.05 for c in texel(x, y)[:3]]
            exponent = math.frexp(max(value))[1]
            out += bytes([int(c * 256 / 2 ** exponent) for c in value] + [exponent + 128])
    return bytes(out)


def standin(name, kind):
    extension = name.rsplit(".", 1)[-1].lower()
    if extension == "dds":
        return dds(kind)
    if kind != "2D":
        return None  # only DDS holds a cube or a volume
    return {"png": png, "tga": tga, "bmp": bmp, "hdr": hdr}.get(extension, lambda: None)()


def warnings(tool, effect):
    with tempfile.TemporaryDirectory() as scratch:
        try:
            result = subprocess.run([tool, "render", str(effect), "--scene", "teapot", "--out",
                                     str(pathlib.Path(scratch) / "frame.png")],
                                    capture_output=True, text=True, timeout=300)
        except subprocess.TimeoutExpired:
            print(f"{effect}: render timed out; no stand-ins", file=sys.stderr)
            return ""
    return result.stdout + result.stderr


def main(tool, root, effects):
    for name in effects:
        effect = pathlib.Path(root) / name
        written = {}
        for _ in range(3):  # missing files, then files of the wrong kind, then a check
            text = warnings(tool, effect)
            wanted = {m: "2D" for m in MISSING.findall(text)}
            wanted.update({m: kind for m, kind in WRONG_KIND.findall(text)})
            wanted = {file: kind for file, kind in wanted.items() if written.get(file) != kind}
            if not wanted:
                break
            for file, kind in wanted.items():
                data = standin(file, kind)
                # The loader reads a Windows path's backslashes as slashes; nothing outside the copy.
                target = (effect.parent / file.replace("\\", "/")).resolve()
                if data is None or not target.is_relative_to(pathlib.Path(root).resolve()):
                    print(f"{name}: no stand-in for '{file}' as a {kind} texture", file=sys.stderr)
                    continue
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_bytes(data)
                written[file] = kind
        else:
            text = warnings(tool, effect)
        for file, kind in sorted(written.items()):
            print(f"{name}: {file} ({kind})")
        for file in sorted(set(MISSING.findall(text)) | {m for m, _ in WRONG_KIND.findall(text)}):
            print(f"{name}: '{file}' still not loaded", file=sys.stderr)


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
