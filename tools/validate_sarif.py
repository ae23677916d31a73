#!/usr/bin/env python3
"""Validates SARIF logs against a SARIF 2.1.0 JSON schema (draft-04) with python3-jsonschema.

The schema is not shipped with massprops (nor in Debian): give its path, e.g. the copy in npm's
@microsoft/jest-sarif package (lib/schemas/sarif-2.1.0-rtm.5.json). As a check of the check, a
copy of each log without its required "version" must fail.

usage: tools/validate_sarif.py SCHEMA.json LOG.sarif [LOG.sarif ...]
"""
import copy
import json
import sys

import jsonschema


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    schema = json.load(open(argv[1], encoding="utf-8"))
    validator = jsonschema.Draft4Validator(schema)
    bad = 0
    for path in argv[2:]:
        log = json.load(open(path, encoding="utf-8"))
        errors = list(validator.iter_errors(log))
        broken = copy.deepcopy(log)
        broken.pop("version", None)
        caught = not validator.is_valid(broken)
        results = sum(len(run.get("results", [])) for run in log.get("runs", []))
        print(f"{path}: {'valid' if not errors else 'INVALID'} ({results} results); "
              f"without 'version': {'rejected' if caught else 'NOT rejected'}")
        for error in errors[:5]:
            print(f"  {'/'.join(map(str, error.absolute_path))}: {error.message}")
        bad += bool(errors) or not caught
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
