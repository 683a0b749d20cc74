#!/usr/bin/env python3
"""Fills a seed directory for one fuzz harness from files already in the tree.

usage: make_seeds.py NAME OUT_DIR
  parse, format, eval, render: every .rts under examples/ and tests/golden/
  obj:                 every .obj under examples/ and tests/ (first 64 KiB of large ones)
  png:                 every small .png under examples/ and tests/, plus a few PNG colour
                       types the tree has none of (gray, gray+alpha, palette, RGBA, 16-bit,
                       interlaced), generated here so the repository stays small.
  lsp:                 LSP sessions (framed JSON-RPC) that open each example and ask for
                       hover, completion, definition, symbols and signature help in it.
"""
import json, os, struct, sys, zlib

MAX_SEED_BYTES = 64 * 1024  # libFuzzer's -max_len below; larger files only slow mutation

# Scenes that exist to run up to a default limit: 10 million loop iterations take about 50 s
# under the sanitizers, and every mutant of them would too, starving the rest of the corpus.
SLOW_SCENES = {"iteration_limit.rts"}

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def files(ext, dirs):
    for d in dirs:
        for base, _, names in os.walk(os.path.join(root, d)):
            for n in sorted(names):
                if n.endswith(ext):
                    yield os.path.join(base, n)


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png(width, height, bit_depth, color_type, rows, plte=None, interlace=0):
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, interlace)
    raw = b"".join(b"\x00" + r for r in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
    if plte:
        out += chunk(b"PLTE", plte)
    return out + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def generated_pngs():
    w, h = 3, 2
    yield "gen_gray8.png", png(w, h, 8, 0, [bytes([0, 128, 255])] * h)
    yield "gen_gray16.png", png(w, h, 16, 0, [struct.pack(">3H", 0, 30000, 65535)] * h)
    yield "gen_gray1.png", png(w, h, 1, 0, [bytes([0b10100000])] * h)
    yield "gen_gray_alpha.png", png(w, h, 8, 4, [bytes([0, 255, 128, 128, 255, 0])] * h)
    yield "gen_palette.png", png(w, h, 8, 3, [bytes([0, 1, 2])] * h, plte=bytes([255, 0, 0, 0, 255, 0, 0, 0, 255]))
    yield "gen_palette2.png", png(w, h, 2, 3, [bytes([0b00011000])] * h, plte=bytes([9, 9, 9, 200, 100, 0, 1, 2, 3]))
    yield "gen_rgba8.png", png(w, h, 8, 6, [bytes(range(12))] * h)
    yield "gen_rgb16.png", png(w, h, 16, 2, [struct.pack(">9H", *range(0, 9 * 7281, 7281))] * h)
    # Adam7: a 1-pixel image is the one interlaced layout that needs no pass splitting.
    yield "gen_interlaced.png", png(1, 1, 8, 2, [bytes([10, 20, 30])], interlace=1)


def lsp_session(text, uri="file:///fuzz/scene.rts"):
    """A byte stream as an editor writes it; the first byte is fuzz_lsp's split point."""
    def msg(obj):
        body = json.dumps(obj).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body
    doc = {"uri": uri}
    out = msg({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
    out += msg({"jsonrpc": "2.0", "method": "initialized", "params": {}})
    out += msg({"jsonrpc": "2.0", "method": "textDocument/didOpen",
                "params": {"textDocument": dict(doc, languageId="rts", version=1, text=text)}})
    lines = text.split("\n")
    for i, method in enumerate(["hover", "completion", "definition", "signatureHelp"]):
        line = (i * 7) % max(1, len(lines))
        pos = {"line": line, "character": len(lines[line]) // 2}
        out += msg({"jsonrpc": "2.0", "id": 10 + i, "method": "textDocument/" + method,
                    "params": {"textDocument": doc, "position": pos}})
    out += msg({"jsonrpc": "2.0", "method": "textDocument/didChange",
                "params": {"textDocument": dict(doc, version=2), "contentChanges": [
                    {"range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 3}},
                     "text": "let"}]}})
    out += msg({"jsonrpc": "2.0", "id": 20, "method": "textDocument/documentSymbol", "params": {"textDocument": doc}})
    out += msg({"jsonrpc": "2.0", "id": 21, "method": "textDocument/formatting",
                "params": {"textDocument": doc, "options": {"tabSize": 4, "insertSpaces": True}}})
    out += msg({"jsonrpc": "2.0", "id": 22, "method": "shutdown"})
    out += msg({"jsonrpc": "2.0", "method": "exit"})
    return bytes([len(out) % 251]) + out


def main():
    name, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    count = 0

    def put(base, data):
        nonlocal count
        with open(os.path.join(out, f"{count:04d}_{base}"), "wb") as f:
            f.write(data[:MAX_SEED_BYTES])
        count += 1

    if name in ("parse", "format", "eval", "render"):
        for p in files(".rts", ["examples", "tests/golden"]):
            if name not in ("parse", "format") and os.path.basename(p) in SLOW_SCENES:
                continue
            put(os.path.basename(p), open(p, "rb").read())
    elif name == "obj":
        for p in files(".obj", ["examples", "tests"]):
            put(os.path.basename(p), open(p, "rb").read())
    elif name == "png":
        for p in files(".png", ["examples", "tests"]):
            if os.path.getsize(p) <= MAX_SEED_BYTES:
                put(os.path.basename(p), open(p, "rb").read())
        for base, data in generated_pngs():
            put(base, data)
    elif name == "pov":
        for p in list(files(".pov", ["tests"])) + list(files(".inc", ["tests"])):
            put(os.path.basename(p), open(p, "rb").read())
    elif name == "lsp":
        for p in files(".rts", ["examples"]):
            text = open(p, "rb").read().decode("utf-8", "replace")
            put(os.path.basename(p) + ".lsp", lsp_session(text))
    else:
        sys.exit(f"make_seeds.py: unknown harness '{name}' (parse, format, eval, obj, png, render, pov, lsp)")
    print(f"{count} seeds for {name} in {out}")


main()
