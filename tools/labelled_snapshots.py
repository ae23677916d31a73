#!/usr/bin/env python3
"""Write the repository trees that ../shared/labelled's files come from, meshes included.

usage: tools/labelled_snapshots.py GITDIRS SNAPSHOTS [--labelled DIR]

GITDIRS holds one git directory per repository, named OWNER+NAME (a bare repository, or a folder
holding `.git` or `repo`); SNAPSHOTS is a folder outside every repository. For every distinct
(repository, commit) of the labelled sets' manifest.tsv, the tree of that commit is written to
SNAPSHOTS/OWNER+NAME/COMMIT/ (COMMIT as the manifest spells it). When the git directory lacks that
commit, the tree of its newest commit (HEAD) is written there instead. Blobs absent from the git
directory (snapshots may leave out large files) are skipped. SNAPSHOTS/sources.tsv records, per
(repository, manifest commit): the commit written, the files written and the files absent.

Nothing is built or run from the trees: they are data for tools/labelled_meshes.py.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


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


def find_git_dir(gitdirs, repo):
    base = os.path.join(gitdirs, repo.replace('/', '+'))
    for candidate in (os.path.join(base, 'repo'), os.path.join(base, '.git'), base, base + '.git'):
        if os.path.isfile(os.path.join(candidate, 'HEAD')):
            return candidate
    return None


def git(git_dir, *args, data=None):
    return subprocess.run(['git', '--git-dir=' + git_dir] + list(args), input=data,
                          capture_output=True, check=False)


def write_tree(git_dir, commit, out):
    """Writes every present blob of commit's tree under out; returns (written, absent)."""
    listing = git(git_dir, 'ls-tree', '-r', '-z', commit).stdout.split(b'\0')
    entries = []
    for item in listing:
        if not item:
            continue
        meta, path = item.split(b'\t', 1)
        mode, kind, sha = meta.split(b' ')
        if kind == b'blob':
            entries.append((mode, sha.decode(), path.decode('utf-8', 'surrogateescape')))
    written = absent = 0
    batch = subprocess.Popen(['git', '--git-dir=' + git_dir, 'cat-file', '--batch'],
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    for mode, sha, path in entries:
        batch.stdin.write((sha + '\n').encode())
        batch.stdin.flush()
        header = batch.stdout.readline().split()
        if len(header) < 3 or header[1] == b'missing':
            absent += 1
            continue
        body = batch.stdout.read(int(header[2]))
        batch.stdout.read(1)  # the newline after the object
        target = os.path.join(out, path)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if mode == b'120000':  # a symbolic link: keep its target as a link
            if not os.path.lexists(target):
                os.symlink(body.decode('utf-8', 'surrogateescape'), target)
        else:
            with open(target, 'wb') as f:
                f.write(body)
        written += 1
    batch.stdin.close()
    batch.wait()
    return written, absent


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('gitdirs')
    parser.add_argument('snapshots')
    parser.add_argument('--labelled', default=os.path.join(HERE, '..', '..', 'shared', 'labelled'))
    args = parser.parse_args()
    seen = set()
    sources = os.path.join(args.snapshots, 'sources.tsv')
    os.makedirs(args.snapshots, exist_ok=True)
    lines = [] if os.path.exists(sources) else [
        'repo\tmanifest_commit\tcommit_written\tfiles_written\tfiles_absent']
    for row in manifest_rows(args.labelled):
        key = (row['repo'], row['commit'])
        if key in seen:
            continue
        seen.add(key)
        git_dir = find_git_dir(args.gitdirs, row['repo'])
        if git_dir is None:
            lines.append(f"{row['repo']}\t{row['commit']}\tnone\t0\t0")
            print(f"{row['repo']}: no git directory", file=sys.stderr)
            continue
        commit = row['commit']
        if git(git_dir, 'cat-file', '-e', commit + '^{commit}').returncode != 0:
            commit = git(git_dir, 'rev-parse', 'HEAD').stdout.decode().strip()
        out = os.path.join(args.snapshots, row['repo'].replace('/', '+'), row['commit'])
        if os.path.isdir(out):
            print(f'{out}: already there, left as it is', file=sys.stderr)
            continue
        written, absent = write_tree(git_dir, commit, out)
        lines.append(f"{row['repo']}\t{row['commit']}\t{commit}\t{written}\t{absent}")
        print(f"{row['repo']} {row['commit'][:10]} -> {commit[:10]}: {written} files, "
              f'{absent} absent', file=sys.stderr)
    if lines:
        with open(sources, 'a', encoding='utf-8') as f:
            f.write('\n'.join(lines) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
