#!/usr/bin/env python3
"""`massprops lsp` driven over standard input and output by a scripted client (issue 45).

Every expected value comes from the tool's other commands or from the file, never from this
script: the diagnostics are compared with `massprops check --format json` on the same file (its
rules, lines, severities and headlines), the code action's edit with the file `massprops fix -o`
writes, the hover's mass with the `<mass value>` written in the file. The corrected forearm
inertia is the solid box's, from the rigid-body table (m(b^2 + c^2)/12 about each axis of a box
b x c x L; hand-derived, as the example's own comment says).

Usage: lsp_cli_test.py MASSPROPS EXAMPLES_DIR [TEST_NAME...]
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from lsp_client import Client, uri_of  # noqa: E402

TOOL = None
EXAMPLE = None
LSP_SEVERITY = {"error": 1, "warning": 2, "note": 3}


def run_json(*args):
    out = subprocess.run([TOOL, *args], capture_output=True, text=True, check=False)
    return json.loads(out.stdout)


def check_json(path):
    """[(rule, 0-based line, LSP severity, headline)] of `check --format json PATH`, sorted."""
    report = run_json("check", "--format", "json", str(path))
    rows = []
    for file in report["files"]:
        for f in file["findings"]:
            rows.append((f["rule"], f["line"] - 1, LSP_SEVERITY[f["severity"]], f["headline"]))
        for e in file["errors"]:
            rows.append(("read-error", max(0, (e["line"] or 1) - 1), 1, None))
    return sorted(rows)


def diagnostic_rows(diagnostics):
    return sorted((d["code"], d["range"]["start"]["line"], d["severity"], d["message"])
                  for d in diagnostics)


def same_findings(diagnostics, expected):
    """The diagnostics are check's findings: same rule, line and severity, and each message
    starts with check's headline."""
    got = diagnostic_rows(diagnostics)
    assert [r[:3] for r in got] == [r[:3] for r in expected], (got, expected)
    for row, want in zip(got, expected):
        if want[3] is not None:
            assert row[3].split("\n")[0] == want[3], (row[3], want[3])


def started():
    client = Client(TOOL)
    reply = client.initialize()
    caps = reply["result"]["capabilities"]
    assert caps["textDocumentSync"]["change"] == 1, caps  # full sync
    assert caps["hoverProvider"] is True, caps
    return client


def line_of(text, needle, after=0):
    """0-based line of the first line at or after `after` that holds `needle`."""
    lines = text.split("\n")
    for i in range(after, len(lines)):
        if needle in lines[i]:
            return i
    raise AssertionError("no line holds " + needle)


def valid_forearm(text):
    """The example with the forearm's ixx replaced by the solid box's (0.8 kg, 4 x 4 x 25 cm):
    ixx = m(b^2 + c^2)/12 with b = 0.04, c = 0.25 m (the rigid-body table)."""
    ixx = 0.8 * (0.04 ** 2 + 0.25 ** 2) / 12
    start = text.index('<link name="forearm">')
    at = text.index('ixx="0.0046"', start)
    return text[:at] + 'ixx="%.9g"' % ixx + text[at + len('ixx="0.0046"'):]


def test_open_example_publishes_the_findings_check_reports():
    client = started()
    try:
        text = EXAMPLE.read_text()
        uri = client.open(EXAMPLE, text)
        published = client.diagnostics(uri)
        expected = check_json(EXAMPLE)
        assert expected, "check reports nothing on the example"
        same_findings(published["diagnostics"], expected)
        lines = text.split("\n")
        rules = {r["id"]: r["severity"] for r in run_json("check", "--list-rules", "--format",
                                                            "json")}
        for d in published["diagnostics"]:
            assert d["source"] == "massprops"
            line = lines[d["range"]["start"]["line"]]
            # The range spans the element's line from its first non-blank character to its end.
            assert d["range"]["start"]["character"] == len(line) - len(line.lstrip()), d
            assert d["range"]["end"] == {"line": d["range"]["start"]["line"],
                                         "character": len(line)}, d
            href = d["codeDescription"]["href"]
            assert href.endswith("rules.md#%s-%s" % (d["code"], rules[d["code"]])), href
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def test_a_valid_forearm_inertia_takes_its_diagnostic_away_in_the_next_publish():
    client = started()
    try:
        text = EXAMPLE.read_text()
        uri = client.open(EXAMPLE, text)
        first = client.diagnostics(uri)["diagnostics"]
        forearm_line = line_of(text, "<inertia ", line_of(text, '<link name="forearm">'))
        at_forearm = [d for d in first if d["range"]["start"]["line"] == forearm_line
                      and d["code"] == "inertia-not-physical"]
        assert at_forearm, first
        client.change(uri, valid_forearm(text), 2)
        second = client.diagnostics(uri)
        assert second["version"] == 2, second
        assert not [d for d in second["diagnostics"] if d["code"] == "inertia-not-physical"], second
        # Everything else stays: it is what check says of the edited file.
        with tempfile.TemporaryDirectory() as folder:
            edited = pathlib.Path(folder) / EXAMPLE.name
            edited.write_text(valid_forearm(text))
            same_findings(second["diagnostics"], check_json(edited))
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def test_only_the_newest_text_of_a_burst_of_changes_is_checked():
    client = started()
    try:
        text = EXAMPLE.read_text()
        uri = client.open(EXAMPLE, text)
        client.diagnostics(uri)
        # Eight changes in one write (well under a pipe's 64 KiB, so they arrive together): the
        # server reads them all before it checks, so it publishes once, for version 9.
        burst = b""
        from lsp_client import frame
        for version in range(2, 10):
            body = valid_forearm(text) if version == 9 else text.replace("2.0", "2.%d" % version)
            burst += frame({"jsonrpc": "2.0", "method": "textDocument/didChange",
                            "params": {"textDocument": {"uri": uri, "version": version},
                                       "contentChanges": [{"text": body}]}})
        assert len(burst) < 60000, len(burst)
        client.send_raw(burst)
        published = client.diagnostics(uri)
        assert published["version"] == 9, published["version"]
        reply = client.call("textDocument/hover", {"textDocument": {"uri": uri},
                                                   "position": {"line": 0, "character": 0}})
        assert "error" not in reply, reply
        # No other publish came between: the hover's answer is the next message.
        assert client.messages.empty(), "a stale check was published"
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def test_hover_on_upper_arm_shows_the_mass_written_in_the_file():
    client = started()
    try:
        text = EXAMPLE.read_text()
        uri = client.open(EXAMPLE, text)
        client.diagnostics(uri)
        link_line = line_of(text, '<link name="upper_arm">')
        block = text[text.index('<link name="upper_arm">'):]
        block = block[:block.index("</link>")]
        mass = re.search(r'<mass value="([^"]+)"', block).group(1)
        xyz = re.search(r'<origin xyz="([^"]+)"', block).group(1).split()
        character = text.split("\n")[link_line].index("<link") + 2
        reply = client.call("textDocument/hover", {"textDocument": {"uri": uri},
                                                   "position": {"line": link_line,
                                                                "character": character}})
        hover = reply["result"]["contents"]
        assert hover["kind"] == "markdown", hover
        assert "upper_arm" in hover["value"], hover["value"]
        assert "| mass | %s kg |" % mass in hover["value"], hover["value"]
        com = "(" + ", ".join("%g" % float(v) for v in xyz) + ")"
        assert com in hover["value"], (com, hover["value"])
        # The forearm is welded to tool0 by a fixed joint: its hover names the group.
        forearm = line_of(text, '<link name="forearm">')
        reply = client.call("textDocument/hover", {"textDocument": {"uri": uri},
                                                   "position": {"line": forearm, "character": 4}})
        assert "welded group" in reply["result"]["contents"]["value"], reply
        assert "`tool0`" in reply["result"]["contents"]["value"], reply
        # Both hovers' tables (the link's and the group's composite) have a header row that says
        # something: CommonMark tables (GFM) render an empty one as a blank band.
        tables = header_rows(hover["value"]) + header_rows(reply["result"]["contents"]["value"])
        assert len(tables) == 3, tables
        assert tables[0] == ["mass", "%s kg" % mass], tables
        assert tables[2][0] == "composite mass", tables
        for cells in tables:
            assert all(cells), tables
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def header_rows(markdown):
    """The cells of each Markdown table's header row: the line above each `|---|...|` line."""
    lines = markdown.split("\n")
    return [[cell.strip() for cell in lines[i - 1].strip().strip("|").split("|")]
            for i in range(1, len(lines)) if re.fullmatch(r"\|(-+\|)+", lines[i].strip())]


def apply_edits(text, edits):
    """Applies LSP TextEdits (positions in UTF-16 units; the example is ASCII) to text."""
    lines = text.split("\n")
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line) + 1)

    def offset(position):
        return offsets[position["line"]] + position["character"]

    for edit in sorted(edits, key=lambda e: offset(e["range"]["start"]), reverse=True):
        start, end = offset(edit["range"]["start"]), offset(edit["range"]["end"])
        text = text[:start] + edit["newText"] + text[end:]
    return text


def code_actions(client, uri, diagnostic):
    reply = client.call("textDocument/codeAction", {
        "textDocument": {"uri": uri}, "range": diagnostic["range"],
        "context": {"diagnostics": [diagnostic]}})
    return reply["result"]


def fixed_text(*args):
    with tempfile.TemporaryDirectory() as folder:
        out = pathlib.Path(folder) / "fixed.urdf"
        subprocess.run([TOOL, "fix", str(EXAMPLE), "-o", str(out), *args], capture_output=True,
                       check=False)
        return out.read_text()


def test_the_code_action_on_the_forearm_error_makes_the_change_fix_makes():
    client = started()
    try:
        text = EXAMPLE.read_text()
        uri = client.open(EXAMPLE, text)
        diagnostics = client.diagnostics(uri)["diagnostics"]
        forearm = next(d for d in diagnostics if d["code"] == "inertia-not-physical")
        actions = code_actions(client, uri, forearm)
        quick = [a for a in actions if a["kind"] == "quickfix"]
        assert len(quick) == 1, actions
        assert quick[0]["isPreferred"] is True
        edits = quick[0]["edit"]["changes"][uri]
        # Minimal: one edit inside the forearm's <inertia> line.
        assert len(edits) == 1 and edits[0]["range"]["start"]["line"] == \
            edits[0]["range"]["end"]["line"] == forearm["range"]["start"]["line"], edits
        fixed = fixed_text()
        assert fixed != text, "fix changed nothing"
        assert apply_edits(text, edits) == fixed
        # A heuristic repair is offered only as a rewrite named for its rule, never preferred;
        # with the forearm's quick fix it makes what `fix --apply units-suspect` writes.
        units = next(d for d in diagnostics if d["code"] == "units-suspect")
        named = code_actions(client, uri, units)
        assert named and all(a["kind"] == "refactor.rewrite" and not a["isPreferred"] and
                             "--apply units-suspect" in a["title"] for a in named), named
        both = apply_edits(apply_edits(text, named[0]["edit"]["changes"][uri]), edits)
        assert both == fixed_text("--apply", "units-suspect")
        # A client that asks for quick fixes only gets none for the guess.
        reply = client.call("textDocument/codeAction", {
            "textDocument": {"uri": uri}, "range": units["range"],
            "context": {"diagnostics": [units], "only": ["quickfix"]}})
        assert reply["result"] == [], reply
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def test_a_malformed_buffer_is_a_read_error_diagnostic_and_the_server_lives_on():
    client = started()
    try:
        uri = client.open(EXAMPLE, '<robot name="r">\n  <link name="a">\n  <link name="b"/>\n')
        published = client.diagnostics(uri)["diagnostics"]
        assert [d["code"] for d in published] == ["read-error"], published
        client.change(uri, EXAMPLE.read_text(), 2)
        same_findings(client.diagnostics(uri)["diagnostics"], check_json(EXAMPLE))
        # Garbage on the wire is answered with a parse error, and the server goes on.
        client.send_raw(b"Content-Length: 5\r\n\r\n{nope")
        error = client.wait_for(lambda m: "error" in m and m.get("id") is None)
        assert error["error"]["code"] == -32700, error
        client.send_raw(b"Content-Type: x\r\n\r\n")  # a header without Content-Length
        error = client.wait_for(lambda m: "error" in m and m.get("id") is None)
        assert error["error"]["code"] == -32700, error
        reply = client.call("textDocument/nonsense", {})
        assert reply["error"]["code"] == -32601, reply
        # Parameters of the wrong shape: InvalidParams (JSON-RPC), the server goes on.
        reply = client.call("textDocument/hover", [1, 2])
        assert reply["error"]["code"] == -32602, reply
        reply = client.call("textDocument/hover", {"textDocument": {"uri": "file:///nowhere.urdf"},
                                                   "position": {"line": 0, "character": 0}})
        assert reply["result"] is None, reply
        client.notify("textDocument/didClose", {"textDocument": {"uri": uri}})
        assert client.diagnostics(uri)["diagnostics"] == []
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def test_the_configuration_and_the_target_are_honoured():
    with tempfile.TemporaryDirectory() as folder:
        copy = pathlib.Path(folder) / EXAMPLE.name
        copy.write_text(EXAMPLE.read_text())
        # .massprops.toml beside the file: check reads it, and so does the server.
        (pathlib.Path(folder) / ".massprops.toml").write_text(
            '[rules]\nunits-suspect = "off"\ninertial-missing = "error"\n')
        client = started()
        try:
            uri = client.open(copy, copy.read_text())
            expected = check_json(copy)
            assert "units-suspect" not in [r[0] for r in expected], expected
            same_findings(client.diagnostics(uri)["diagnostics"], expected)
            # An invalid configuration is a diagnostic, as it stops check.
            (pathlib.Path(folder) / ".massprops.toml").write_text("[rules]\nno-such-rule = 1\n")
            client.notify("textDocument/didSave", {"textDocument": {"uri": uri}})
            published = client.diagnostics(uri)["diagnostics"]
            assert [d["code"] for d in published] == ["config-error"], published
            assert ".massprops.toml" in published[0]["message"], published
            assert client.shutdown_and_exit() == 0
        finally:
            client.kill()
        # initializationOptions' target: the findings of `check --target mujoco`.
        (pathlib.Path(folder) / ".massprops.toml").unlink()
        client = Client(TOOL)
        try:
            client.initialize({"target": "mujoco"})
            uri = client.open(copy, copy.read_text())
            report = run_json("check", "--format", "json", "--target", "mujoco", str(copy))
            expected = sorted((f["rule"], f["line"] - 1, LSP_SEVERITY[f["severity"]],
                               f["headline"]) for file in report["files"] for f in file["findings"])
            assert expected != check_json(copy), "the target changes nothing on the example"
            same_findings(client.diagnostics(uri)["diagnostics"], expected)
            assert client.shutdown_and_exit() == 0
        finally:
            client.kill()


WELDED = """<robot name="r">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <link name="arm"/>
  <joint name="w" type="fixed"><parent link="arm"/><child link="tip"/></joint>
  <link name="tip"/>
</robot>
"""


def test_a_welded_group_finding_lists_its_members_as_related_information():
    with tempfile.TemporaryDirectory() as folder:
        path = pathlib.Path(folder) / "welded.urdf"
        path.write_text(WELDED)
        # arm and tip (welded by the fixed joint w) turn on j with no mass: one group finding.
        report = run_json("check", "--format", "json", str(path))
        group = [f for f in report["files"][0]["findings"] if f["values"].get("group_links") == 2]
        assert len(group) == 1, report
        client = started()
        try:
            uri = client.open(path, WELDED)
            published = client.diagnostics(uri)["diagnostics"]
            finding = next(d for d in published if d["code"] == group[0]["rule"])
            related = finding["relatedInformation"]
            assert sorted(r["location"]["range"]["start"]["line"] for r in related) == \
                [line_of(WELDED, '<link name="arm"/>'), line_of(WELDED, '<link name="tip"/>')]
            assert all(r["location"]["uri"] == uri for r in related), related
            assert sorted(r["message"].split("'")[1] for r in related) == ["arm", "tip"], related
            # The same members as check's JSON `group` (the finding's data, not re-derived).
            assert [r["message"].split("'")[1] for r in related] == group[0]["group"], related
            assert client.shutdown_and_exit() == 0
        finally:
            client.kill()


def test_meshes_resolve_from_the_file_s_place_for_an_unsaved_buffer():
    # Links whose only geometry is a mesh (../mesh/*.stl, relative to the file): their findings
    # need the meshes' sizes. The buffer has one line more than the file on disk, not saved.
    path = EXAMPLE.parent.parent / "testdata" / "check" / "mesh-only-absurd-inertia.urdf"
    on_disk = path.read_text()
    declaration, rest = on_disk.split("\n", 1)
    assert declaration.startswith("<?xml"), declaration
    buffer = declaration + "\n<!-- not saved -->\n" + rest
    expected = [(rule, line + 1, severity, headline)
                for rule, line, severity, headline in check_json(path)]
    assert len(expected) >= 2, expected  # without the meshes check finds nothing here
    client = started()
    try:
        uri = client.open(path, buffer)
        same_findings(client.diagnostics(uri)["diagnostics"], sorted(expected))
        assert client.shutdown_and_exit() == 0
    finally:
        client.kill()


def test_ranges_count_utf16_units_and_uris_are_percent_decoded():
    # A folder whose name needs percent-encoding in a URI, and a line with characters outside
    # ASCII, one of them outside the Basic Multilingual Plane (two UTF-16 code units).
    with tempfile.TemporaryDirectory() as folder:
        place = pathlib.Path(folder) / "robot é 1%"
        place.mkdir()
        path = place / "a.urdf"
        text = ('<robot name="r">\n  <link name="a">\n    <inertial>\n      <mass value="1"/>\n'
                '      <inertia ixx="1" iyy="1" izz="5" ixy="0" ixz="0" iyz="0"/> <!-- kg·m² 𝑰 -->\n'
                '    </inertial>\n  </link>\n</robot>\n')
        path.write_text(text)
        expected = check_json(path)
        assert ("inertia-not-physical", 4) in [r[:2] for r in expected], expected
        client = started()
        try:
            uri = client.open(path, text)
            assert "%20" in uri and "%C3%A9" in uri, uri
            published = client.diagnostics(uri)
            assert published["uri"] == uri
            same_findings(published["diagnostics"], expected)
            line = text.split("\n")[4]
            end = len(line.encode("utf-16-le")) // 2  # UTF-16 code units (LSP's default)
            assert end == len(line) + 1  # the one character outside the BMP counts twice
            at = next(d for d in published["diagnostics"] if d["code"] == "inertia-not-physical")
            assert at["range"]["end"] == {"line": 4, "character": end}, at
            assert client.shutdown_and_exit() == 0
        finally:
            client.kill()


def test_exit_without_shutdown_is_exit_code_1():
    client = started()
    try:
        client.notify("exit", None)
        client.proc.stdin.close()
        assert client.proc.wait(timeout=30) == 1
    finally:
        client.kill()


XACRO = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="unused" value="1"/>
  <link name="base">
    <inertial>
      <mass value="1"/>
      <inertia ixx="1" iyy="1" izz="5" ixy="0" ixz="0" iyz="0"/>
    </inertial>
  </link>
</robot>
"""

# A stand-in expander (CI has no ROS xacro): drops the xacro namespace and properties, which is
# what xacro makes of the file above. It reads its standard input first: an expander that took
# the server's (the editor's message stream) would hang the session.
EXPANDER = """import re, sys
sys.stdin.read()  # reads standard input to its end: under the server, never the editor's messages
text = open(sys.argv[1]).read()
text = re.sub(r' xmlns:xacro="[^"]*"', "", text)
sys.stdout.write("".join(l for l in text.splitlines(True) if "xacro:property" not in l))
"""


def xacro_package(folder, text):
    """A package (package.xml) holding robot.urdf.xacro with `text`, and the expander."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "package.xml").write_text("<package><name>r</name></package>\n")
    (folder / "robot.urdf.xacro").write_text(text)
    (folder / "expand.py").write_text(EXPANDER)
    return folder / "robot.urdf.xacro"


def xacro_check(path):
    """[(rule, 0-based source line)] of `check FILE.xacro --format json` with the expander."""
    report = run_json("check", "--format", "json", "--xacro-command",
                      "%s %s" % (sys.executable, path.parent / "expand.py"), str(path))
    return sorted((f["rule"], f["source"]["line"] - 1) for file in report["files"]
                  for f in file["findings"])


def test_a_xacro_buffer_is_checked_at_the_xacro_lines_it_holds():
    with tempfile.TemporaryDirectory() as folder:
        path = xacro_package(pathlib.Path(folder) / "pkg", XACRO)
        client = Client(TOOL, ["--xacro-command", "%s %s" % (sys.executable,
                                                            path.parent / "expand.py")])
        try:
            client.initialize()
            uri = client.open(path, XACRO)
            published = client.diagnostics(uri)["diagnostics"]
            expected = xacro_check(path)
            assert ("inertia-not-physical", line_of(XACRO, "<inertia ")) in expected, expected
            assert sorted((d["code"], d["range"]["start"]["line"]) for d in published) == \
                expected, (published, expected)
            # Two lines more above the link, not saved: the diagnostics follow the buffer's lines,
            # as check finds them in a package whose file holds the edited text.
            edited = XACRO.replace("  <link", "  <!-- a -->\n  <!-- b -->\n  <link")
            client.change(uri, edited, 2)
            published = client.diagnostics(uri)["diagnostics"]
            expected = xacro_check(xacro_package(pathlib.Path(folder) / "copy", edited))
            assert ("inertia-not-physical", line_of(edited, "<inertia ")) in expected, expected
            assert sorted((d["code"], d["range"]["start"]["line"]) for d in published) == \
                expected, (published, expected)
            # The buffer's file beside the document is gone; the file on disk is unchanged.
            assert sorted(p.name for p in path.parent.iterdir()) == \
                ["expand.py", "package.xml", "robot.urdf.xacro"]
            assert path.read_text() == XACRO
            assert client.shutdown_and_exit() == 0
        finally:
            client.kill()


def main():
    global TOOL, EXAMPLE
    TOOL = sys.argv[1]
    EXAMPLE = pathlib.Path(sys.argv[2]).resolve() / "two_link_arm.urdf"
    wanted = sys.argv[3:]
    tests = [(name, f) for name, f in globals().items() if name.startswith("test_")]
    failed = 0
    ran = 0
    for name, test in tests:
        if wanted and name not in wanted:
            continue
        ran += 1
        try:
            test()
            print("ok  ", name)
        except Exception as error:  # report every test, then fail
            failed += 1
            print("FAIL", name, repr(error)[:3000])
    if ran == 0:
        print("FAIL no test named", wanted)
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
