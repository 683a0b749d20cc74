#!/usr/bin/env python3
"""Draws a terminal screen captured with its colours (tmux capture-pane -e) into a PNG.

usage: ansi_to_png.py SCREEN.ansi OUT.png COLUMNS ROWS

Understands the SGR codes tmux writes: 16/256/RGB colours, bold, reverse, underline (drawn as a
line), and resets. One cell per character, DejaVu Sans Mono; no scaling, no effects.
"""
import re, sys
from PIL import Image, ImageDraw, ImageFont

src, out, cols, rows = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"
BOLD = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono-Bold.ttf"
SIZE = 15
font, bold_font = ImageFont.truetype(FONT, SIZE), ImageFont.truetype(BOLD, SIZE)
cw = int(round(font.getlength("M")))
ch = SIZE + 5

# xterm's palette: 16 base colours, a 6x6x6 cube, a gray ramp.
BASE = [(0, 0, 0), (205, 49, 49), (13, 188, 121), (229, 229, 16), (36, 114, 200), (188, 63, 188), (17, 168, 205),
        (229, 229, 229), (102, 102, 102), (241, 76, 76), (35, 209, 139), (245, 245, 67), (59, 142, 234),
        (214, 112, 214), (41, 184, 219), (255, 255, 255)]
def palette(n):
    if n < 16:
        return BASE[n]
    if n < 232:
        n -= 16
        steps = [0, 95, 135, 175, 215, 255]
        return (steps[n // 36], steps[(n // 6) % 6], steps[n % 6])
    v = 8 + 10 * (n - 232)
    return (v, v, v)

DEFAULT_FG, DEFAULT_BG = (220, 220, 220), (24, 24, 28)
img = Image.new("RGB", (cols * cw + 16, rows * ch + 16), DEFAULT_BG)
draw = ImageDraw.Draw(img)
lines = open(src, encoding="utf-8", errors="replace").read().split("\n")[:rows]
fg, bg, is_bold, reverse, underline = None, None, False, False, False
for y, line in enumerate(lines):
    x = 0
    for token in re.split(r"(\x1b\[[0-9;:]*m)", line):
        m = re.fullmatch(r"\x1b\[([0-9;:]*)m", token)
        if m:
            codes = [int(c.split(":")[0] or 0) for c in (m.group(1) or "0").split(";")]
            i = 0
            while i < len(codes):
                c = codes[i]
                if c == 0:
                    fg, bg, is_bold, reverse, underline = None, None, False, False, False
                elif c == 1: is_bold = True
                elif c == 22: is_bold = False
                elif c == 4: underline = True
                elif c == 24: underline = False
                elif c == 7: reverse = True
                elif c == 27: reverse = False
                elif 30 <= c <= 37: fg = palette(c - 30)
                elif 90 <= c <= 97: fg = palette(c - 90 + 8)
                elif 40 <= c <= 47: bg = palette(c - 40)
                elif 100 <= c <= 107: bg = palette(c - 100 + 8)
                elif c == 39: fg = None
                elif c == 49: bg = None
                elif c in (38, 48) and i + 1 < len(codes):
                    if codes[i + 1] == 5 and i + 2 < len(codes):
                        col = palette(codes[i + 2]); i += 2
                    elif codes[i + 1] == 2 and i + 4 < len(codes):
                        col = tuple(codes[i + 2:i + 5]); i += 4
                    else:
                        col = None
                    if c == 38: fg = col
                    else: bg = col
                i += 1
            continue
        for char in token:
            if x >= cols:
                break
            f, b = fg or DEFAULT_FG, bg or DEFAULT_BG
            if reverse:
                f, b = b, f
            px, py = 8 + x * cw, 8 + y * ch
            draw.rectangle([px, py, px + cw - 1, py + ch - 1], fill=b)
            if char != " ":
                draw.text((px, py + 2), char, font=bold_font if is_bold else font, fill=f)
            if underline:
                draw.line([px, py + ch - 2, px + cw - 1, py + ch - 2], fill=f)
            x += 1
img.save(out)
