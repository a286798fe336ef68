# Converts an X window dump (xwd, 24/32-bit ZPixmap) to a PNG, optionally cropped: for the
# pictures of the window in docs/ (scripts/window-shots.sh, scripts/window-path.sh). Usage: xwd2png.py in.xwd out.png [x y w h]
import struct, sys, zlib
# usage: xwd2png.py in.xwd out.png [x y w h]
data = open(sys.argv[1], 'rb').read()
hdr = struct.unpack('>25I', data[:100])
header_size, version, fmt, depth, width, height = hdr[0], hdr[1], hdr[2], hdr[3], hdr[4], hdr[5]
byte_order = hdr[7]; bpp = hdr[11]; bpl = hdr[12]; ncolors = hdr[19]
off = header_size + ncolors * 12
x0, y0, w, h = 0, 0, width, height
if len(sys.argv) > 3:
    x0, y0, w, h = map(int, sys.argv[3:7])
rows = []
for y in range(y0, y0 + h):
    row = bytearray(b'\x00')
    base = off + y * bpl
    for x in range(x0, x0 + w):
        p = base + x * (bpp // 8)
        if byte_order == 0:  # LSB first: B G R X
            b, g, r = data[p], data[p+1], data[p+2]
        else:
            r, g, b = data[p+1], data[p+2], data[p+3]
        row += bytes((r, g, b))
    rows.append(bytes(row))
raw = b''.join(rows)
def chunk(t, d):
    c = struct.pack('>I', len(d)) + t + d
    return c + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
open(sys.argv[2], 'wb').write(png)
