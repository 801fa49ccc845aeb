#!/usr/bin/env python3
"""The glTF files hitops writes: valid for the Khronos validator, and faithful to the input.

Runs hitops with --labels, --parts-glb, --parts-glb-primitives and --labels-glb on the shipped
animal.off and on the textured boxes of make_textured_boxes.py (GLB and .gltf with side-by-side
files), validates every output with validate.js (0 errors), then reads the outputs back:

  * the feature ID of every triangle of the --labels-glb output (in the order hitops reads the
    triangles) is its line of the --labels output, the same at its three corners;
  * each part of the --parts-glb output of a glTF input has the triangles of that part, at the
    same place in the scene (node transforms applied), facing the way their normals say, with
    NORMAL, TEXCOORD_0, COLOR_0, the input's material and its PNG image embedded byte for byte.

  python3 test_gltf_outputs.py HITOPS NODE DATA_DIR WORK_DIR
"""

import collections
import json
import math
import os
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FORMATS = {5120: 'b', 5121: 'B', 5122: 'h', 5123: 'H', 5125: 'I', 5126: 'f'}
WIDTH = {'SCALAR': 1, 'VEC2': 2, 'VEC3': 3, 'VEC4': 4}


class Gltf:
    """A glTF file read back: its JSON and the bytes of its buffers."""

    def __init__(self, path):
        data = open(path, 'rb').read()
        if data[:4] == b'glTF':
            length = struct.unpack_from('<I', data, 12)[0]
            self.json = json.loads(data[20:20 + length])
            self.buffers = [data[28 + length:]]
        else:
            self.json = json.loads(data)
            folder = os.path.dirname(path)
            self.buffers = [open(os.path.join(folder, b['uri']), 'rb').read() for b in self.json['buffers']]

    def view_bytes(self, i):
        view = self.json['bufferViews'][i]
        offset = view.get('byteOffset', 0)
        return self.buffers[view['buffer']][offset:offset + view['byteLength']]

    def accessor(self, i):
        """The elements of accessor i, each a tuple."""
        a = self.json['accessors'][i]
        fmt, n = FORMATS[a['componentType']], WIDTH[a['type']]
        size = struct.calcsize('<' + fmt) * n
        view = self.json['bufferViews'][a['bufferView']]
        stride = view.get('byteStride', size)
        data = self.buffers[view['buffer']]
        base = view.get('byteOffset', 0) + a.get('byteOffset', 0)
        return [struct.unpack_from('<%d%s' % (n, fmt), data, base + k * stride) for k in range(a['count'])]

    def image_bytes(self, i):
        return self.view_bytes(self.json['images'][i]['bufferView'])


def node_matrix(node):
    """The local transform of a node, row-major 4x4."""
    if 'matrix' in node:
        m = node['matrix']
        return [[m[4 * c + r] for c in range(4)] for r in range(4)]
    x, y, z, w = node.get('rotation', [0, 0, 0, 1])
    s = node.get('scale', [1, 1, 1])
    t = node.get('translation', [0, 0, 0])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def multiply(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def apply(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3))


def triangle_primitives(g):
    """(world matrix, primitive, corners of each triangle) of every triangle primitive of the default
    scene, in the order of the package's reader: nodes depth first, primitives, triangles."""
    out = []
    identity = [[float(i == j) for j in range(4)] for i in range(4)]
    stack = [(n, identity) for n in reversed(g.json['scenes'][g.json.get('scene', 0)]['nodes'])]
    while stack:
        n, parent = stack.pop()
        node = g.json['nodes'][n]
        world = multiply(parent, node_matrix(node))
        for p in g.json['meshes'][node['mesh']]['primitives'] if 'mesh' in node else []:
            mode = p.get('mode', 4)
            if mode not in (4, 5, 6):
                continue
            index = [i[0] for i in g.accessor(p['indices'])] if 'indices' in p else \
                list(range(g.json['accessors'][p['attributes']['POSITION']]['count']))
            if mode == 4:
                corners = [index[k:k + 3] for k in range(0, len(index) - 2, 3)]
            elif mode == 5:
                corners = [[index[t], index[t + 1 + t % 2], index[t + 2 - t % 2]] for t in range(len(index) - 2)]
            else:
                corners = [[index[t + 1], index[t + 2], index[0]] for t in range(len(index) - 2)]
            out.append((world, p, corners))
        stack += [(c, world) for c in reversed(node.get('children', []))]
    return out


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def check_labels_glb(path, labels):
    """The feature ID of every triangle, the same at its corners, is its label."""
    g = Gltf(path)
    check('EXT_mesh_features' in g.json.get('extensionsUsed', []), path + ': EXT_mesh_features not declared')
    ids = []
    for _, p, corners in triangle_primitives(g):
        feature = p['extensions']['EXT_mesh_features']['featureIds'][-1]
        check(feature['featureCount'] == max(labels) + 1, path + ': featureCount is not the number of parts')
        values = g.accessor(p['attributes']['_FEATURE_ID_%d' % feature['attribute']])
        for c in corners:
            check(values[c[0]] == values[c[1]] == values[c[2]], path + ': a triangle has several feature IDs')
            ids.append(int(values[c[0]][0]))
    check(ids == labels, path + ': the feature IDs are not the --labels output (%d and %d triangles)' % (len(ids), len(labels)))


def centroid_key(points):
    return tuple(round(sum(p[k] for p in points) / 3, 4) for k in range(3))


def check_part_triangles(g, part, p, input_centroids, path):
    """The triangles of a part primitive: in the input's part, facing the way of their normals."""
    positions = g.accessor(p['attributes']['POSITION'])
    normals = g.accessor(p['attributes']['NORMAL'])
    c = [i[0] for i in g.accessor(p['indices'])]
    for k in range(0, len(c), 3):
        a, b, d = (positions[c[k + j]] for j in range(3))
        e1, e2 = [b[i] - a[i] for i in range(3)], [d[i] - a[i] for i in range(3)]
        face = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        n = [sum(normals[c[k + j]][i] for j in range(3)) for i in range(3)]
        check(sum(face[i] * n[i] for i in range(3)) > 0, path + ': a triangle faces against its normals')
        key = centroid_key((a, b, d))
        check(input_centroids[part][key] > 0, path + ': a triangle of part %d is not one of the input' % part)
        input_centroids[part][key] -= 1


def check_parts_glb(path, input_path, labels):
    """Every triangle of the input is in its part, with the input's attributes and material."""
    g, source = Gltf(path), Gltf(input_path)
    centroids = collections.defaultdict(collections.Counter)
    t = 0
    for world, p, corners in triangle_primitives(source):
        positions = source.accessor(p['attributes']['POSITION'])
        for c in corners:
            centroids[labels[t]][centroid_key([apply(world, positions[i]) for i in c])] += 1
            t += 1
    check(source.json['images'] and 'KHR_texture_transform' in g.json.get('extensionsUsed', []),
          path + ': the texture transform extension is lost')
    png = source.image_bytes(0) if 'bufferView' in source.json['images'][0] else \
        open(os.path.join(os.path.dirname(input_path), source.json['images'][0]['uri']), 'rb').read()
    for mesh in g.json['meshes']:
        if not mesh['name'].startswith('part_'):
            check(mesh['name'].startswith('primitive_'), path + ': unexpected mesh ' + mesh['name'])
            continue
        part = int(mesh['name'][5:])
        for p in mesh['primitives']:
            for name in ('POSITION', 'NORMAL', 'TEXCOORD_0', 'COLOR_0'):
                check(name in p['attributes'], path + ': part %d lost %s' % (part, name))
            material = g.json['materials'][p['material']]
            check(material == source.json['materials'][0], path + ': part %d lost its material' % part)
            texture = g.json['textures'][material['pbrMetallicRoughness']['baseColorTexture']['index']]
            check(g.image_bytes(texture['source']) == png, path + ': the image is not the input\'s')
            check_part_triangles(g, part, p, centroids, path)
    check(all(n == 0 for counter in centroids.values() for n in counter.values()),
          path + ': some triangles of the input are in no part')


def hitops(binary, input_path, out_prefix):
    """Runs hitops with every output; returns the --labels output and the glTF files written."""
    outputs = {'labels': out_prefix + '.seg', 'parts': out_prefix + '_parts.glb', 'labelled': out_prefix + '_labels.glb'}
    subprocess.run([binary, input_path, '--threads', '1', '--labels', outputs['labels'], '--parts-glb',
                    outputs['parts'], '--parts-glb-primitives', '--labels-glb', outputs['labelled']], check=True)
    labels = [int(line) for line in open(outputs['labels'])]
    return labels, outputs


def main():
    binary, node, data, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    subprocess.run([sys.executable, os.path.join(HERE, 'make_textured_boxes.py'), work], check=True)
    inputs = [os.path.join(data, 'animal.off'), os.path.join(work, 'boxes.glb'), os.path.join(work, 'boxes.gltf')]
    runs = []
    for i, input_path in enumerate(inputs):
        labels, outputs = hitops(binary, input_path, os.path.join(work, 'out_%d' % i))
        runs.append((input_path, labels, outputs))
    written = [r[2][k] for r in runs for k in ('parts', 'labelled')]
    subprocess.run([node, os.path.join(HERE, 'validate.js')] + written, check=True)
    for input_path, labels, outputs in runs:
        check_labels_glb(outputs['labelled'], labels)
        if input_path.endswith(('.glb', '.gltf')):
            check(len(set(labels)) >= 2, input_path + ': the two boxes should be two parts')
            check_parts_glb(outputs['parts'], input_path, labels)
    print('glTF outputs: valid, labels and parts read back as written')


if __name__ == '__main__':
    main()
