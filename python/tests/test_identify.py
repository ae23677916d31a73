"""massprops.identify (docs/identify.md): the report of `massprops identify --format json` as
Python data. The recording is testdata/identify/planar_arm.csv, whose torques
tools/make_identify_csv.py computes from the closed-form planar two-link arm (Spong, Hutchinson
and Vidyasagar 2006, section 7.4) of a true arm other than planar_arm.urdf, with noise sigma =
0.01 N.m; the planar arm has 6 inertial base parameters (Khalil and Dombre 2002, section 12.4),
plus 3 friction terms per joint: rank 12 of 26. The same samples are also written here as a
ROS 2 bag by Python's own sqlite3 and struct (a CDR encoder apart from both massprops' reader and
the C++ tests' writer)."""
import csv
import json
import sqlite3
import struct
import subprocess

import pytest

import massprops


def planar(testdata):
    return testdata / "identify" / "planar_arm.urdf", testdata / "identify" / "planar_arm.csv"


def test_identify_reports_the_true_arms_fit(testdata):
    robot, data = planar(testdata)
    r = massprops.identify(robot, data, validate=0.25)
    assert r["identifiability"]["parameters"] == 26
    assert r["identifiability"]["rank"] == 12
    assert r["training_samples"] == 600 and r["validation_samples"] == 200
    assert [j["joint"] for j in r["joints"]] == ["shoulder", "elbow"]
    for j in r["joints"]:
        assert j["rms_identified"] < 0.012  # the noise is 0.01
        assert j["rms_file"] > 0.05
    assert all(link["identified_consistent"] for link in r["links"])


@pytest.mark.parametrize("model", ["planar_arm.urdf", "planar_arm_boxes.urdf"])
def test_identify_equals_the_commands_json(testdata, tool, model):
    # planar_arm_boxes.urdf: a box per link, so each link's estimate is bounded by its box's
    # ellipsoid in both (geometry_bound true for both links).
    robot, data = testdata / "identify" / model, planar(testdata)[1]
    out = subprocess.run([tool, "identify", "--format", "json", "--validate", "0.3", str(robot),
                          str(data)], check=True, capture_output=True, text=True).stdout
    r = massprops.identify(str(robot), str(data))
    assert r == json.loads(out)
    assert r["geometry_bound_links"] == (2 if model == "planar_arm_boxes.urdf" else 0)


def _cdr_joint_state(sec, nanosec, names, position, velocity, effort):
    """sensor_msgs/msg/JointState as little-endian CDR: primitives aligned to their size from the
    end of the 4-byte encapsulation header; strings with their NUL in the length."""
    out = bytearray(b"\x00\x01\x00\x00")

    def align(n):
        out.extend(b"\x00" * ((-(len(out) - 4)) % n))

    def u32(x):
        align(4)
        out.extend(struct.pack("<I", x))

    def string(s):
        u32(len(s) + 1)
        out.extend(s.encode() + b"\x00")

    def doubles(xs):
        u32(len(xs))
        for x in xs:
            align(8)
            out.extend(struct.pack("<d", x))

    align(4)
    out.extend(struct.pack("<i", sec))
    u32(nanosec)
    string("base_link")
    u32(len(names))
    for n in names:
        string(n)
    doubles(position)
    doubles(velocity)
    doubles(effort)
    return bytes(out)


def test_identify_reads_a_bag_written_by_python(testdata, tmp_path):
    robot, data = planar(testdata)
    rows = [r for r in csv.reader(open(data)) if r and not r[0].startswith("#")]
    header, rows = rows[0], rows[1:]
    col = {name: i for i, name in enumerate(header)}
    bag = tmp_path / "bag"
    bag.mkdir()
    (bag / "metadata.yaml").write_text("rosbag2_bagfile_information:\n  version: 5\n")
    db = sqlite3.connect(bag / "bag_0.db3")
    db.execute("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT "
               "NULL, serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL)")
    db.execute("CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
               "timestamp INTEGER NOT NULL, data BLOB NOT NULL)")
    db.execute("INSERT INTO topics VALUES(1, '/joint_states', 'sensor_msgs/msg/JointState', "
               "'cdr', '')")
    for row in rows:
        ns = round(float(row[col["time"]]) * 1e9)
        joints = ["elbow", "shoulder"]  # not the model's order
        message = _cdr_joint_state(
            1700000000 + ns // 10**9, ns % 10**9, joints,
            [float(row[col[j + ".q"]]) for j in joints],
            [float(row[col[j + ".dq"]]) for j in joints],
            [float(row[col[j + ".tau"]]) for j in joints])
        db.execute("INSERT INTO messages(topic_id, timestamp, data) VALUES(1, ?, ?)", (ns, message))
    db.commit()
    db.close()
    r = massprops.identify(robot, bag)
    assert r["identifiability"]["rank"] == 12
    assert r["training_samples"] + r["validation_samples"] == len(rows)
    for j in r["joints"]:
        # Accelerations derived from the velocities (JointState has none): within 1.5 times
        # the noise.
        assert j["rms_identified"] < 0.015
    assert all(link["identified_consistent"] for link in r["links"])


def test_identify_errors(testdata, tmp_path):
    robot, data = planar(testdata)
    with pytest.raises(massprops.ReadError):
        massprops.identify(robot, tmp_path / "missing.csv")
    with pytest.raises(ValueError, match="validate"):
        massprops.identify(robot, data, validate=0.95)
    wrong = tmp_path / "wrong.csv"
    wrong.write_text("time,shoulder.q,shoulder.tau\n" +
                     "".join(f"{k / 100},0,0\n" for k in range(12)))
    with pytest.raises(ValueError, match="joint 'elbow' of the model has no columns"):
        massprops.identify(robot, wrong)
