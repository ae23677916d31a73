#!/usr/bin/env python3
"""Runs `massprops check` on ../shared/labelled's files with their meshes (docs/labels.md).

usage: tools/labelled_meshes.py BUILD SNAPSHOTS OUT [--labelled DIR] [-- CHECK-ARGS...]

BUILD is a build folder holding `massprops` (or the `massprops` executable itself); SNAPSHOTS the
folder tools/labelled_snapshots.py wrote (SNAPSHOTS/OWNER+NAME/COMMIT/ holds a repository's tree
at a manifest commit); OUT a folder for the results. For every file of setN/files/ (setN/manifest.tsv
gives its repository, commit and path), the file is checked AT ITS PLACE in the snapshot, so that
relative mesh paths and file:// URIs resolve from there:

  BUILD/massprops check --format json --package-path P... --model-path M... PLACE [CHECK-ARGS]

When the snapshot's file at `path` differs from the labelled one (the snapshot is of another
commit) or is missing, the labelled bytes are written beside it as `labelled_NN_name.ext` and that
copy is checked. Without a snapshot, the labelled file is checked where it is (no mesh resolves).

Package paths come from the file's own `package://NAME/...` URIs: among the folders of the
snapshot whose package.xml names NAME, or that are named NAME, the one holding the most of the
file's meshes of that package (then: an ancestor of the file; then the shortest path) is the
package, and its parent folder is passed (massprops looks for DIR/NAME and for DIR's subfolders
whose package.xml names NAME). When no folder so named holds all of them, but another folder of
the snapshot holds more (a package that its build installs under another name than its source
folder's: iCub_creo2urdf/ as package iCub), OUT/links/setN/FILE/NAME is made a symbolic link to
that folder and OUT/links/setN/FILE is passed; the table says so. `model://NAME...` URIs and SDF
includes get --model-path the same way, plus setN/modelpath/ when it exists.

Prints one line per file (mesh links, resolved, unresolved, findings) and writes to OUT:
  resolution.tsv   the same table,
  findings.jsonl   one line per finding: set, file, rule, severity, link, message,
  json/setN/FILE.json   check's JSON output, as it came.
"""
import argparse
import hashlib
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
URI = re.compile(r'(package|model)://([^/"\'<>\s]+)/?([^"\'<>\s]*)')


def manifest_rows(labelled):
    rows = []
    for set_name in sorted(os.listdir(labelled)):
        manifest = os.path.join(labelled, set_name, 'manifest.tsv')
        if not os.path.isfile(manifest):
            continue
        with open(manifest, encoding='utf-8') as f:
            header = f.readline().rstrip('\n').split('\t')
            for line in f:
                if line.strip():
                    rows.append(dict(zip(header, line.rstrip('\n').split('\t')), set=set_name))
    return rows


def commits_written(snapshots):
    """(repo, manifest commit) -> commit written, from SNAPSHOTS/sources.tsv."""
    written = {}
    path = os.path.join(snapshots, 'sources.tsv')
    if os.path.isfile(path):
        with open(path, encoding='utf-8') as f:
            header = f.readline().rstrip('\n').split('\t')
            for line in f:
                row = dict(zip(header, line.rstrip('\n').split('\t')))
                written[(row['repo'], row['manifest_commit'])] = row['commit_written']
    return written


class Tree:
    """The folders of one snapshot tree, indexed by name and by package.xml name."""

    def __init__(self, root):
        self.root = root
        self.by_name = {}
        self.folders = []
        for folder, subfolders, files in os.walk(root):
            subfolders[:] = [s for s in subfolders if s != '.git']
            self.folders.append(folder)
            self.by_name.setdefault(os.path.basename(folder), []).append(folder)
            if 'package.xml' in files:
                name = package_xml_name(os.path.join(folder, 'package.xml'))
                if name and name != os.path.basename(folder):
                    self.by_name.setdefault(name, []).append(folder)

    def best_folder(self, name, rests, place):
        """(folder, named): the folder standing for package or model `name`. named: it is named
        so (by its name or its package.xml); else it is the folder of the tree that holds the
        most of `rests` (a package installed under another name than its source folder's).
        (None, False) when no folder holds any of them and none is named so."""
        rests = sorted(set(rests))

        def found(folder):
            return sum(os.path.exists(os.path.join(folder, rest)) for rest in rests)

        def score(folder):
            ancestor = os.path.abspath(place).startswith(os.path.abspath(folder) + os.sep)
            return (-found(folder), not ancestor, len(folder), folder)

        candidates = self.by_name.get(name, [])
        best = min(candidates, key=score) if candidates else None
        if best is not None and found(best) == len(rests):
            return best, True
        holder = min(self.folders, key=score) if rests else None
        if holder is not None and found(holder) > (found(best) if best else 0):
            return holder, False
        return best, best is not None


def package_xml_name(path):
    try:
        name = ET.parse(path).getroot().find('name')
    except (ET.ParseError, OSError):
        return None
    return name.text.strip() if name is not None and name.text else None


def search_paths(text, tree, place, links):
    """(package paths, model paths, notes) for the URIs and includes of a file's text. A package
    found under another folder name gets a symbolic link `links`/NAME to its folder (as an
    install would name it), and `links` is passed."""
    wanted = {'package': {}, 'model': {}}
    for scheme, name, rest in URI.findall(text):
        wanted[scheme].setdefault(name, []).append(rest)
    paths = {'package': [], 'model': []}
    notes = []
    for scheme, names in wanted.items():
        for name, rests in sorted(names.items()):
            folder, named = tree.best_folder(name, rests, place) if tree else (None, False)
            if folder is None:
                continue
            parent = os.path.dirname(folder)
            if not named:
                os.makedirs(links, exist_ok=True)
                link = os.path.join(links, name)
                if os.path.islink(link):
                    os.unlink(link)
                os.symlink(os.path.abspath(folder), link)
                parent = links
                notes.append(f'{scheme}://{name} -> {os.path.relpath(folder, tree.root)}')
            if parent not in paths[scheme]:
                paths[scheme].append(parent)
    return paths['package'], paths['model'], notes


def digest(path):
    with open(path, 'rb') as f:
        return hashlib.sha256(f.read()).hexdigest()


def place_file(labelled_file, root, path):
    """Where to check the file: (path, how), writing the labelled bytes when needed."""
    if root is None:
        return labelled_file, 'no snapshot'
    in_place = os.path.join(root, path)
    if os.path.isfile(in_place) and digest(in_place) == digest(labelled_file):
        return in_place, 'in place'
    copy = os.path.join(os.path.dirname(in_place), 'labelled_' + os.path.basename(labelled_file))
    os.makedirs(os.path.dirname(copy), exist_ok=True)
    with open(labelled_file, 'rb') as source, open(copy, 'wb') as target:
        target.write(source.read())
    return copy, 'copy beside ' + ('a different file' if os.path.isfile(in_place) else 'nothing')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('build')
    parser.add_argument('snapshots')
    parser.add_argument('out')
    parser.add_argument('--labelled', default=os.path.join(HERE, '..', '..', 'shared', 'labelled'))
    parser.add_argument('check_args', nargs='*', help='more arguments for check, after --')
    args = parser.parse_args()
    tool = args.build if os.path.isfile(args.build) else os.path.join(args.build, 'massprops')
    written = commits_written(args.snapshots)
    trees = {}
    table = ['set\tfile\trepo\tmanifest_commit\tcommit_checked\tchecked_as\tmesh_links\tresolved'
             '\tunresolved\tfirst_unresolved\terrors\twarnings\tnotes\tread_errors\tlinked_packages']
    findings_out = []
    print(f"{'file':52} {'checked as':28} mesh-links resolved unresolved  E  W  N")
    for row in manifest_rows(args.labelled):
        labelled_file = os.path.join(args.labelled, row['set'], 'files', row['file'])
        root = os.path.join(args.snapshots, row['repo'].replace('/', '+'), row['commit'])
        if not os.path.isdir(root):
            root = None
        if root is not None and root not in trees:
            trees[root] = Tree(root)
        place, how = place_file(labelled_file, root, row['path'])
        with open(labelled_file, encoding='utf-8', errors='replace') as f:
            text = f.read()
        links = os.path.abspath(os.path.join(args.out, 'links', row['set'], row['file']))
        package_paths, model_paths, notes = search_paths(text, trees.get(root), place, links)
        modelpath = os.path.join(args.labelled, row['set'], 'modelpath')
        if os.path.isdir(modelpath):
            model_paths.append(os.path.abspath(modelpath))
        command = [tool, 'check', '--format', 'json']
        for folder in package_paths:
            command += ['--package-path', folder]
        for folder in model_paths:
            command += ['--model-path', folder]
        command += [place] + args.check_args
        run = subprocess.run(command, capture_output=True, text=True, check=False)
        json_dir = os.path.join(args.out, 'json', row['set'])
        os.makedirs(json_dir, exist_ok=True)
        with open(os.path.join(json_dir, row['file'] + '.json'), 'w', encoding='utf-8') as f:
            f.write(run.stdout)
        try:
            document = json.loads(run.stdout)
        except json.JSONDecodeError:
            print(f"{row['set']}/{row['file']}: check gave no JSON (exit {run.returncode}): "
                  f'{run.stderr.strip()[:300]}', file=sys.stderr)
            continue
        summary = document['summary']
        mesh_links = summary.get('mesh_links', 0)
        unresolved = summary.get('mesh_links_unresolved', 0)
        for file_result in document['files']:
            for finding in file_result['findings']:
                findings_out.append({'set': row['set'], 'file': row['file'],
                                     'rule': finding['rule'], 'severity': finding['severity'],
                                     'link': finding['link'], 'message': finding['message']})
        commit = written.get((row['repo'], row['commit']), row['commit'] if root else 'none')
        table.append('\t'.join(str(v) for v in (
            row['set'], row['file'], row['repo'], row['commit'], commit, how, mesh_links,
            mesh_links - unresolved, unresolved, summary.get('first_unresolved_mesh') or '',
            summary['errors'], summary['warnings'], summary['notes'], summary['read_errors'],
            '; '.join(notes))))
        print(f"{row['set'] + '/' + row['file']:52.52} {how:28} {mesh_links:10} "
              f"{mesh_links - unresolved:8} {unresolved:10} {summary['errors']:2} "
              f"{summary['warnings']:2} {summary['notes']:2}")
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, 'resolution.tsv'), 'w', encoding='utf-8') as f:
        f.write('\n'.join(table) + '\n')
    with open(os.path.join(args.out, 'findings.jsonl'), 'w', encoding='utf-8') as f:
        for finding in findings_out:
            f.write(json.dumps(finding) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
