#!/usr/bin/env python3
"""A scripted LSP client: drives `rts lsp` over stdio with raw JSON-RPC, as an editor does, through
initialize, open, change, hover, completion, definition (a variable, a macro in an included file,
the include itself), document symbols, signature help, formatting, shutdown and exit, and checks
each answer.

usage: client_test.py RTS_BINARY SOURCE_DIR
"""
import json, os, subprocess, sys, tempfile, threading, time

rts, src = sys.argv[1], sys.argv[2]
failures = []


def check(cond, what):
    print(("ok: " if cond else "FAIL: ") + what)
    if not cond:
        failures.append(what)


class Client:
    def __init__(self, cwd):
        self.p = subprocess.Popen([rts, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, cwd=cwd)
        self.next_id = 1
        self.notifications = []
        # A watchdog: a hung server fails the test instead of hanging CTest.
        self.timer = threading.Timer(30, self.p.kill)
        self.timer.start()

    def send(self, obj):
        body = json.dumps(obj).encode()
        self.p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.p.stdin.flush()

    def read(self):
        header = b""
        while not header.endswith(b"\r\n\r\n"):
            c = self.p.stdout.read(1)
            if not c:
                raise RuntimeError("the server closed its output")
            header += c
        length = next(int(l.split(b":")[1]) for l in header.split(b"\r\n") if l.lower().startswith(b"content-length"))
        return json.loads(self.p.stdout.read(length))

    def request(self, method, params=None):
        rid = self.next_id
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": rid, "method": method, "params": params or {}})
        while True:
            m = self.read()
            if m.get("id") == rid:
                return m
            self.notifications.append(m)

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def diagnostics(self, uri):
        """Waits for the next diagnostics published for uri."""
        while True:
            for i, m in enumerate(self.notifications):
                if m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri:
                    del self.notifications[: i + 1]
                    return m["params"]
            self.notifications.append(self.read())


start = time.monotonic()
with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(tmp, "shapes.rts"), "w") as f:
        f.write("// A ball of radius r.\nmacro ball(c, r = 1) { sphere { center = c radius = r } }\n")
    scene = os.path.join(tmp, "scene.rts")
    uri = "file://" + scene
    text = ('include "shapes.rts"\n'
            "let size = 2\n"
            "camera { position = <0, 1, -5> look_at = <0, 0, 0> }\n"
            "point_light { position = <5, 5, -5> }\n"
            "ball(<0, 0, 0>, size)\n"
            "sphere { center = <1, 0, 0> radius = 1 raduis = 2 }\n")
    # Not saved: the server must analyse the buffer's text, with includes beside its path.
    c = Client(tmp)
    init = c.request("initialize", {"processId": os.getpid(), "rootUri": "file://" + tmp, "capabilities": {}})
    caps = init["result"]["capabilities"]
    check(caps["hoverProvider"] and caps["definitionProvider"] and "completionProvider" in caps, "initialize: capabilities")
    check(caps["positionEncoding"] == "utf-16", "initialize: UTF-16 positions by default")
    c.notify("initialized", {})
    c.notify("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "rts", "version": 1, "text": text}})
    d = c.diagnostics(uri)
    check(len(d["diagnostics"]) == 1, "open: one diagnostic")
    diag = d["diagnostics"][0]
    check(diag["range"] == {"start": {"line": 5, "character": 39}, "end": {"line": 5, "character": 45}},
          "open: the diagnostic covers 'raduis' exactly: %s" % diag["range"])
    check("did you mean 'radius'" in diag["message"] and diag["severity"] == 1, "open: message and severity")

    # Fix the typo with a range edit: no diagnostics.
    c.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 2}, "contentChanges": [
        {"range": {"start": {"line": 5, "character": 38}, "end": {"line": 5, "character": 49}}, "text": ""}]})
    d = c.diagnostics(uri)
    check(d["version"] == 2 and d["diagnostics"] == [], "change: the fixed buffer has no diagnostics")

    h = c.request("textDocument/hover", {"textDocument": {"uri": uri}, "position": {"line": 2, "character": 11}})
    value = h["result"]["contents"]["value"]
    check("**position** (camera property)" in value and "<0, 0, -5>" in value, "hover: camera.position from the table")
    h = c.request("textDocument/hover", {"textDocument": {"uri": uri}, "position": {"line": 4, "character": 18}})
    check("Value: `2`" in h["result"]["contents"]["value"], "hover: a variable's value")
    h = c.request("textDocument/hover", {"textDocument": {"uri": uri}, "position": {"line": 4, "character": 1}})
    check("macro ball(c, r = 1)" in h["result"]["contents"]["value"] and "A ball of radius r." in h["result"]["contents"]["value"],
          "hover: a macro from an included file, with its comment")

    comp = c.request("textDocument/completion", {"textDocument": {"uri": uri}, "position": {"line": 3, "character": 13}})
    labels = {i["label"] for i in comp["result"]["items"]}
    check({"position", "intensity", "shadows", "size", "ball", "sphere", "sqrt"} <= labels and "radius" not in labels,
          "completion: the light's properties, names in scope, kinds and builtins")

    df = c.request("textDocument/definition", {"textDocument": {"uri": uri}, "position": {"line": 4, "character": 18}})
    check(df["result"] == {"uri": uri, "range": {"start": {"line": 1, "character": 4}, "end": {"line": 1, "character": 8}}},
          "definition: a variable")
    df = c.request("textDocument/definition", {"textDocument": {"uri": uri}, "position": {"line": 4, "character": 2}})
    check(df["result"] and df["result"]["uri"].endswith("/shapes.rts") and df["result"]["range"]["start"] == {"line": 1, "character": 6},
          "definition: a macro in an included file")
    df = c.request("textDocument/definition", {"textDocument": {"uri": uri}, "position": {"line": 0, "character": 12}})
    check(df["result"] and df["result"]["uri"].endswith("/shapes.rts"), "definition: the include's file")

    sym = c.request("textDocument/documentSymbol", {"textDocument": {"uri": uri}})
    names = [s["name"] for s in sym["result"]]
    check(names == ["size", "camera", "point_light", "ball()", "sphere"], "symbols: %s" % names)

    c.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 3}, "contentChanges": [
        {"range": {"start": {"line": 6, "character": 0}, "end": {"line": 6, "character": 0}}, "text": "ball(<1, 2, 3>, "}]})
    sig = c.request("textDocument/signatureHelp", {"textDocument": {"uri": uri}, "position": {"line": 6, "character": 16}})
    check(sig["result"] and sig["result"]["signatures"][0]["label"] == "ball(c, r = 1)" and sig["result"]["activeParameter"] == 1,
          "signature help: the second parameter of an included macro")

    # Formatting through rts fmt's formatter: while the buffer does not parse, a clear refusal;
    # then one edit giving the canonical layout, which rts fmt itself agrees with.
    fmt = c.request("textDocument/formatting", {"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": True}})
    check(fmt.get("error", {}).get("code") == -32803 and "does not parse" in fmt["error"]["message"],
          "formatting: refused with the syntax error while the buffer does not parse")
    c.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": 4}, "contentChanges": [
        {"text": "let   size=2\nsphere{center=<0,1,0> radius=size}\n"}]})
    fmt = c.request("textDocument/formatting", {"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": True}})
    edits = fmt.get("result") or []
    expected = subprocess.run([rts, "fmt", "-"], input=b"let   size=2\nsphere{center=<0,1,0> radius=size}\n",
                              capture_output=True).stdout.decode()
    check(caps["documentFormattingProvider"] and len(edits) == 1 and edits[0]["newText"] == expected
          and edits[0]["range"]["start"] == {"line": 0, "character": 0},
          "formatting: one edit with rts fmt's text (%r)" % expected)

    bad = c.request("no/such/method", {})
    check(bad.get("error", {}).get("code") == -32601, "unknown method: MethodNotFound")
    c.p.stdin.write(b"Content-Length: 9\r\n\r\n{garbage}")
    c.p.stdin.flush()
    m = c.read()
    check(m.get("id") is None and m.get("error", {}).get("code") == -32700, "malformed JSON: a parse error response")

    check(c.request("shutdown")["result"] is None, "shutdown")
    c.notify("exit", None)
    code = c.p.wait(timeout=10)
    c.timer.cancel()
    check(code == 0, "exit after shutdown: status 0")

elapsed = time.monotonic() - start
print("%.2f s" % elapsed)
if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("all passed")
