#!/usr/bin/env python3
"""Writes a synthetic serial chain of N links, for the reading benchmarks.

Usage: gen_chain.py N OUT [--sdf | --world | --welded | --massless]

Each link has an <inertial> (a 1.5 kg box 0.04 x 0.04 x 0.1 m about its center, which is 0.05 m
up the link's z axis) and a matching collision box; link k-1 and link k are joined by a revolute
joint about y, 0.1 m apart. URDF by default; --sdf writes the same chain as SDF 1.9; --world
writes an SDF 1.9 world of N links in as many models as it takes: chains of WORLD_CHAIN links
each (the last one shorter), standing 1 m apart on a square grid (a swarm, a multi-robot world).
--welded writes the URDF chain with every joint fixed (one welded group of N links: what a
per-link question over its group would make quadratic); --massless the URDF chain whose links
have mass 0 and a zero inertia but the last (every moving body asks what is outboard of it).
bench/read_bench.cc builds byte-identical URDF text in C++ (MakeChainUrdf), so its numbers hold
for the files this script writes.
"""
import sys

# Box inertia about its center: m/12 (b^2 + c^2) etc. with m = 1.5, sides 0.04, 0.04, 0.1.
IXX = "0.00145"
IZZ = "0.0004"


def urdf_chain(n, joint_type="revolute", massless=False):
    out = ['<?xml version="1.0"?>\n<robot name="chain">\n']
    for k in range(n):
        light = massless and k < n - 1
        mass, ixx, izz = ("0", "0", "0") if light else ("1.5", IXX, IZZ)
        out.append(
            f'  <link name="link{k}">\n'
            f'    <inertial>\n'
            f'      <origin xyz="0 0 0.05" rpy="0 0 0"/>\n'
            f'      <mass value="{mass}"/>\n'
            f'      <inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{ixx}" iyz="0" izz="{izz}"/>\n'
            f'    </inertial>\n'
            f'    <collision>\n'
            f'      <origin xyz="0 0 0.05" rpy="0 0 0"/>\n'
            f'      <geometry><box size="0.04 0.04 0.1"/></geometry>\n'
            f'    </collision>\n'
            f'  </link>\n')
        if k > 0:
            out.append(
                f'  <joint name="joint{k}" type="{joint_type}">\n'
                f'    <origin xyz="0 0 0.1" rpy="0 0 0"/>\n'
                f'    <parent link="link{k - 1}"/>\n'
                f'    <child link="link{k}"/>\n'
                f'    <axis xyz="0 1 0"/>\n'
                f'    <limit lower="-1.57" upper="1.57" effort="10" velocity="1"/>\n'
                f'  </joint>\n')
    out.append('</robot>\n')
    return ''.join(out)


def sdf_chain(n):
    out = ['<?xml version="1.0"?>\n<sdf version="1.9">\n  <model name="chain">\n']
    out.extend(sdf_links(n, '    '))
    out.append('  </model>\n</sdf>\n')
    return ''.join(out)


# Links per model of a --world.
WORLD_CHAIN = 8


def sdf_links(n, indent):
    """The links and joints of an SDF chain of n links, each line indented by `indent`."""
    out = []
    for k in range(n):
        name = f'link{k}'
        out.append(
            f'{indent}<link name="{name}">\n'
            f'{indent}  <pose>0 0 {0.1 * k:.12g} 0 0 0</pose>\n'
            f'{indent}  <inertial>\n'
            f'{indent}    <pose>0 0 0.05 0 0 0</pose>\n'
            f'{indent}    <mass>1.5</mass>\n'
            f'{indent}    <inertia><ixx>{IXX}</ixx><ixy>0</ixy><ixz>0</ixz>'
            f'<iyy>{IXX}</iyy><iyz>0</iyz><izz>{IZZ}</izz></inertia>\n'
            f'{indent}  </inertial>\n'
            f'{indent}  <collision name="box">\n'
            f'{indent}    <pose>0 0 0.05 0 0 0</pose>\n'
            f'{indent}    <geometry><box><size>0.04 0.04 0.1</size></box></geometry>\n'
            f'{indent}  </collision>\n'
            f'{indent}</link>\n')
        if k > 0:
            out.append(
                f'{indent}<joint name="joint{k}" type="revolute">\n'
                f'{indent}  <parent>link{k - 1}</parent>\n'
                f'{indent}  <child>{name}</child>\n'
                f'{indent}  <axis><xyz>0 1 0</xyz>'
                f'<limit><lower>-1.57</lower><upper>1.57</upper></limit></axis>\n'
                f'{indent}</joint>\n')
    return out


def sdf_world(n):
    models = (n + WORLD_CHAIN - 1) // WORLD_CHAIN
    side = 1
    while side * side < models:
        side += 1
    out = ['<?xml version="1.0"?>\n<sdf version="1.9">\n  <world name="swarm">\n']
    for m in range(models):
        links = min(WORLD_CHAIN, n - m * WORLD_CHAIN)
        out.append(f'    <model name="robot{m}">\n'
                   f'      <pose>{m % side} {m // side} 0 0 0 0</pose>\n')
        out.extend(sdf_links(links, '      '))
        out.append('    </model>\n')
    out.append('  </world>\n</sdf>\n')
    return ''.join(out)


def main(argv):
    kinds = ('--sdf', '--world', '--welded', '--massless')
    if len(argv) not in (3, 4) or (len(argv) == 4 and argv[3] not in kinds):
        sys.stderr.write(__doc__)
        return 2
    n = int(argv[1])
    if n < 1:
        sys.stderr.write('N must be at least 1\n')
        return 2
    kind = argv[3] if len(argv) == 4 else '--urdf'
    text = {'--sdf': sdf_chain, '--world': sdf_world, '--urdf': urdf_chain,
            '--welded': lambda n: urdf_chain(n, joint_type="fixed"),
            '--massless': lambda n: urdf_chain(n, massless=True)}[kind](n)
    with open(argv[2], 'w', encoding='utf-8', newline='\n') as f:
        f.write(text)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
