# The robot descriptions of this package, checked by massprops as one of its tests
# (`colcon test` runs it with pytest, like the ament linters; docs/ci.md, "Python packages").
import pathlib

import massprops

PACKAGE = pathlib.Path(__file__).resolve().parents[1]
FAIL_ON = ("error",)  # ("error", "warning") to fail on warnings too


def test_descriptions_have_no_findings_at_the_fail_level():
    found = [finding for path in sorted(PACKAGE.glob("urdf/*.urdf"))
             for finding in massprops.check(path) if finding.severity in FAIL_ON]
    assert not found, "\n".join(str(finding) for finding in found)
