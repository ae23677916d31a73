"""A minimal Language Server Protocol client over a child process's standard input and output,
for the tests of `massprops lsp` (tests/lsp_cli_test.py, tests/lsp_bad_input_test.py) and the
benchmark (bench/lsp_bench.py). Framing per LSP 3.17's base protocol: `Content-Length: N\\r\\n\\r\\n`
then N bytes of JSON."""
import json
import os
import pathlib
import queue
import subprocess
import tempfile
import threading
import time
import urllib.parse


def uri_of(path):
    return "file://" + urllib.parse.quote(str(pathlib.Path(path).resolve()))


def frame(message):
    body = json.dumps(message).encode("utf-8")
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


class Client:
    """Starts `TOOL lsp ARGS...`; a thread reads its messages into a queue."""

    def __init__(self, tool, args=(), cwd=None):
        self.stderr = tempfile.TemporaryFile()
        self.proc = subprocess.Popen([tool, "lsp", *args], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=self.stderr, cwd=cwd)
        self.messages = queue.Queue()
        self.next_id = 1
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        out = self.proc.stdout
        while True:
            length = None
            while True:
                line = out.readline()
                if not line:
                    self.messages.put(None)
                    return
                line = line.strip()
                if not line:
                    break
                name, _, value = line.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value)
            body = out.read(length)
            self.messages.put((time.monotonic(), json.loads(body)))

    def send_raw(self, data):
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def send(self, message):
        self.send_raw(frame(message))

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def request(self, method, params):
        """Sends a request and returns its id."""
        request_id = self.next_id
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": request_id, "method": method, "params": params})
        return request_id

    def wait_for(self, predicate, timeout=60):
        """The first message (in arrival order) for which predicate(message) is true; the
        messages before it are dropped. Raises AssertionError on timeout or end of output."""
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError("no expected message from the server in %s s" % timeout)
            try:
                item = self.messages.get(timeout=left)
            except queue.Empty:
                continue
            if item is None:
                raise AssertionError("the server closed its output; stderr:\n" + self.stderr_text())
            self.last_arrival, message = item
            if predicate(message):
                return message

    def call(self, method, params, timeout=60):
        request_id = self.request(method, params)
        reply = self.wait_for(lambda m: m.get("id") == request_id and "method" not in m, timeout)
        return reply

    def diagnostics(self, uri, timeout=60):
        """The params of the next publishDiagnostics for `uri`."""
        message = self.wait_for(lambda m: m.get("method") == "textDocument/publishDiagnostics"
                                and m["params"]["uri"] == uri, timeout)
        return message["params"]

    def initialize(self, options=None, root=None):
        params = {"processId": os.getpid(), "capabilities": {},
                  "rootUri": uri_of(root) if root else None}
        if options is not None:
            params["initializationOptions"] = options
        reply = self.call("initialize", params)
        self.notify("initialized", {})
        return reply

    def open(self, path, text, version=1, language="xml"):
        uri = uri_of(path)
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": language, "version": version, "text": text}})
        return uri

    def change(self, uri, text, version):
        self.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": version},
                                               "contentChanges": [{"text": text}]})

    def shutdown_and_exit(self, timeout=30):
        """shutdown, exit; returns the process's exit code."""
        reply = self.call("shutdown", None)
        assert "error" not in reply, reply
        self.notify("exit", None)
        self.proc.stdin.close()
        return self.proc.wait(timeout=timeout)

    def stderr_text(self):
        self.stderr.seek(0)
        return self.stderr.read().decode("utf-8", "replace")

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
