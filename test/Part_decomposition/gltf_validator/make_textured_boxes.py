#!/usr/bin/env python3
"""Writes a small textured glTF scene for the test of the glTF writers, in two containers:

  boxes.glb    one binary buffer, the PNG texture in a buffer view
  boxes.gltf   the buffer in boxes.bin and the texture in boxes.png, side by side

The scene: one box mesh (24 vertices: a normal, a UV, a colour per face corner; indexed
triangles; a material with a base colour texture) instanced by two nodes under a rotated and
translated parent: box A as is, box B stretched and mirrored (negative determinant, so the
winding and the normals must follow). The two boxes are far apart, so the decomposition gives
them different parts and the labelled output has to duplicate the shared mesh.

  python3 make_textured_boxes.py OUTPUT_DIR
"""

import json
import os
import struct
import sys
import zlib


def png_bytes(width, height, pixel):
    """An RGB PNG whose pixel (x, y) is pixel(x, y), built chunk by chunk."""
    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)
    rows = b''.join(b'\x00' + b''.join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))
    header = struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)  # 8 bits, RGB
    return b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) + chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b'')


def box():
    """Positions, normals, UVs, colours and indices of a unit box around the origin, outward."""
    positions, normals, uvs, colours, indices = [], [], [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u, v = (axis + 1) % 3, (axis + 2) % 3
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = 0.5 * sign, 0.5 * a, 0.5 * b
                positions.append(p)
                normals.append(n)
                uvs.append([(a + 1) / 2, (b + 1) / 2])
                colours.append([0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.5 + 0.5 * n[2], 1.0])
            quad = [base, base + 1, base + 2, base, base + 2, base + 3]
            if sign < 0:  # counter-clockwise seen from outside
                quad = [base, base + 2, base + 1, base, base + 3, base + 2]
            indices += quad
    return positions, normals, uvs, colours, indices


def scene(image_in_buffer):
    """The glTF JSON and its binary buffer; the image in the buffer or as boxes.png."""
    positions, normals, uvs, colours, indices = box()
    buffer = bytearray()
    views, accessors = [], []

    def add(values, fmt, component_type, kind, target, bounds=False):
        while len(buffer) % 4:
            buffer.append(0)
        flat = [x for v in values for x in (v if isinstance(v, list) else [v])]
        data = struct.pack('<%d%s' % (len(flat), fmt), *flat)
        views.append({'buffer': 0, 'byteOffset': len(buffer), 'byteLength': len(data), 'target': target})
        buffer.extend(data)
        accessor = {'bufferView': len(views) - 1, 'componentType': component_type, 'count': len(values), 'type': kind}
        if bounds:
            accessor['min'] = [min(v[k] for v in values) for k in range(3)]
            accessor['max'] = [max(v[k] for v in values) for k in range(3)]
        accessors.append(accessor)
        return len(accessors) - 1

    attributes = {
        'POSITION': add(positions, 'f', 5126, 'VEC3', 34962, bounds=True),
        'NORMAL': add(normals, 'f', 5126, 'VEC3', 34962),
        'TEXCOORD_0': add(uvs, 'f', 5126, 'VEC2', 34962),
        'COLOR_0': add(colours, 'f', 5126, 'VEC4', 34962),
    }
    index_accessor = add(indices, 'H', 5123, 'SCALAR', 34963)
    png = png_bytes(8, 8, lambda x, y: (255, 200, 0) if (x // 2 + y // 2) % 2 else (30, 60, 200))
    if image_in_buffer:
        while len(buffer) % 4:
            buffer.append(0)
        views.append({'buffer': 0, 'byteOffset': len(buffer), 'byteLength': len(png)})
        buffer.extend(png)
        image = {'bufferView': len(views) - 1, 'mimeType': 'image/png', 'name': 'checker'}
    else:
        image = {'uri': 'boxes.png', 'name': 'checker'}
    gltf = {
        'asset': {'version': '2.0', 'generator': 'make_textured_boxes.py', 'copyright': 'test data'},
        'scene': 0,
        'scenes': [{'nodes': [0]}],
        'nodes': [
            {'name': 'parent', 'children': [1, 2], 'translation': [1.0, 2.0, 3.0],
             'rotation': [0.0, 0.38268343, 0.0, 0.92387953]},
            {'name': 'box_a', 'mesh': 0, 'translation': [-2.0, 0.0, 0.0]},
            {'name': 'box_b', 'mesh': 0, 'translation': [2.0, 0.0, 0.0], 'scale': [-2.0, 0.5, 0.5]},
        ],
        'meshes': [{'name': 'box', 'primitives': [{'attributes': attributes, 'indices': index_accessor,
                                                   'material': 0, 'mode': 4}]}],
        'materials': [{'name': 'checker', 'pbrMetallicRoughness': {
            'baseColorTexture': {'index': 0, 'extensions': {'KHR_texture_transform': {'scale': [2.0, 2.0]}}},
            'metallicFactor': 0.0}}],
        'textures': [{'sampler': 0, 'source': 0}],
        'samplers': [{'magFilter': 9728, 'minFilter': 9728}],
        'images': [image],
        'accessors': accessors,
        'bufferViews': views,
        'buffers': [{'byteLength': len(buffer)}],
        'extensionsUsed': ['KHR_texture_transform'],
    }
    return gltf, bytes(buffer), png


def write_glb(path, gltf, buffer):
    text = json.dumps(gltf).encode()
    text += b' ' * (-len(text) % 4)
    buffer += b'\x00' * (-len(buffer) % 4)
    with open(path, 'wb') as f:
        f.write(struct.pack('<4sII', b'glTF', 2, 12 + 8 + len(text) + 8 + len(buffer)))
        f.write(struct.pack('<I4s', len(text), b'JSON') + text)
        f.write(struct.pack('<I4s', len(buffer), b'BIN\x00') + buffer)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    gltf, buffer, _ = scene(image_in_buffer=True)
    write_glb(os.path.join(out, 'boxes.glb'), gltf, buffer)
    gltf, buffer, png = scene(image_in_buffer=False)
    gltf['buffers'][0]['uri'] = 'boxes.bin'
    with open(os.path.join(out, 'boxes.gltf'), 'w') as f:
        json.dump(gltf, f)
    with open(os.path.join(out, 'boxes.bin'), 'wb') as f:
        f.write(buffer)
    with open(os.path.join(out, 'boxes.png'), 'wb') as f:
        f.write(png)


if __name__ == '__main__':
    main()
