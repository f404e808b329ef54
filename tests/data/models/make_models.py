#!/usr/bin/env python3
"""Writes the small models the assimp loader's tests read (tests/unit/test_assimp.cpp): text
files as they are committed, and checker.png (4x2 RGBA: top row red, bottom row blue) made
with the standard library only. Run from anywhere: python3 make_models.py"""
import os
import struct
import zlib

here = os.path.dirname(os.path.abspath(__file__))


def write(name, text):
    with open(os.path.join(here, name), "w", newline="\n") as f:
        f.write(text.lstrip("\n"))


def png(name, width, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)
    data = (b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, len(rows), 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
    with open(os.path.join(here, name), "wb") as f:
        f.write(data)


# Two objects: a unit quad in z = 0 (normals +z, material "blue") and a triangle in x = 2
# (normals +x, material "half", translucent and two-sided).
write("two_parts.obj", """
# gnomon test model: a quad and a triangle with their own materials
mtllib two_parts.mtl
o quad
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 1
usemtl blue
f 1//1 2//1 3//1 4//1
o tri
v 2 0 0
v 2 0 -1
v 2 1 0
vn 1 0 0
usemtl half
f 5//2 6//2 7//2
""")
write("two_parts.mtl", """
newmtl blue
Kd 0.1 0.2 0.8
Ks 0.5 0.5 0.5
Ns 96
illum 2
newmtl half
Kd 0.25 0.5 0.75
d 0.4
Ns 5000
illum 2
""")

# A textured quad: vt (0, 0) is the bottom-left of the image in OBJ, as in OpenGL.
write("textured.obj", """
# gnomon test model: a quad with a diffuse map
mtllib textured.mtl
v 0 0 0
v 2 0 0
v 2 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
usemtl checker
f 1/1/1 2/2/1 3/3/1 4/4/1
""")
write("textured.mtl", """
newmtl checker
Kd 1 1 1
map_Kd checker.png
""")
png("checker.png", 4, [[(255, 0, 0, 255)] * 4, [(0, 0, 255, 255)] * 4])

# A texture outside the folder: refused with a warning, the material drawn untextured.
write("escape.obj", """
mtllib escape.mtl
v 0 0 0
v 1 0 0
v 0 1 0
vt 0 0
vt 1 0
vt 0 1
usemtl out
f 1/1 2/2 3/3
""")
write("escape.mtl", """
newmtl out
Kd 1 1 1
map_Kd ../gltf/secret.png
""")

# A triangle with a line and a point beside it: the line and point are skipped.
write("with_lines.obj", """
v 0 0 0
v 1 0 0
v 0 1 0
v 5 5 5
f 1 2 3
l 1 4
p 4
""")

# Points only: nothing to draw.
write("points.ply", """
ply
format ascii 1.0
comment gnomon test model: a point cloud
element vertex 3
property float x
property float y
property float z
end_header
0 0 0
1 0 0
0 1 0
""")

# A coloured quad (two triangles sharing an edge), no normals: smooth ones are generated.
write("quad.ply", """
ply
format ascii 1.0
comment gnomon test model: a square with vertex colours
element vertex 4
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 2
property list uchar int vertex_indices
end_header
0 0 0 255 0 0
1 0 0 0 255 0
1 0 1 0 0 255
0 0 1 255 255 255
3 0 2 1
3 0 3 2
""")

# A right-angled wedge: 5 faces, 8 triangles.
facets = []
def tri(a, b, c):
    facets.append((a, b, c))
A, B, C = (0, 0, 0), (1, 0, 0), (0, 1, 0)
D, E, F = (0, 0, 1), (1, 0, 1), (0, 1, 1)
tri(A, C, B); tri(D, E, F)                        # ends
tri(A, B, E); tri(A, E, D)                        # bottom (y = 0)
tri(A, D, F); tri(A, F, C)                        # back (x = 0)
tri(B, C, F); tri(B, F, E)                        # slope
def sub(p, q): return tuple(x - y for x, y in zip(p, q))
def cross(u, v): return (u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0])
def write_stl(name, path):
    """`facets` as an ASCII STL solid called `name`, with each facet's normal."""
    lines = ["solid " + name]
    for a, b, c in facets:
        n = cross(sub(b, a), sub(c, a))
        l = sum(x * x for x in n) ** 0.5
        lines.append("  facet normal %g %g %g" % tuple(x / l for x in n))
        lines.append("    outer loop")
        for p in (a, b, c):
            lines.append("      vertex %g %g %g" % p)
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append("endsolid " + name)
    write(path, "\n".join(lines) + "\n")
write_stl("wedge", "wedge.stl")

# A post as CAD tools export it, Z-up: a 0.2 x 0.3 footprint in x and y at z = 0, 1 tall along
# +z, its top cut on a slant (so the up axis cannot be mistaken for down); 12 triangles.
facets = []
P = [(0, 0, 0), (0.2, 0, 0), (0.2, 0.3, 0), (0, 0.3, 0),
     (0, 0, 1), (0.2, 0, 1), (0.2, 0.3, 0.9), (0, 0.3, 0.9)]
for a, b, c, d in [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6),
                   (3, 0, 4, 7)]:
    tri(P[a], P[b], P[c]); tri(P[a], P[c], P[d])
write_stl("post", "post_z_up.stl")

# Broken: a Collada file cut short (malformed XML), and a PLY face naming a vertex that is
# not there.
write("broken.dae", """
<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_geometries><geometry id="g"><mesh>
""")
write("bad_index.ply", """
ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
element face 1
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
3 0 1 7
""")

# A hierarchy (Collada): a triangle under a translated parent, scaled by 2 and mirrored,
# a point light, a spot light and a camera.
tri_geometry = """
      <node id="{id}" name="{id}">{transform}
        <instance_geometry url="#tri">
          <bind_material><technique_common>
            <instance_material symbol="mat" target="#red"/>
          </technique_common></bind_material>
        </instance_geometry>
      </node>"""
write("hierarchy.dae", """
<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_cameras>
    <camera id="cam" name="cam"><optics><technique_common><perspective>
      <xfov>90</xfov><aspect_ratio>2</aspect_ratio><znear>0.5</znear><zfar>50</zfar>
    </perspective></technique_common></optics></camera>
  </library_cameras>
  <library_lights>
    <light id="lamp" name="lamp"><technique_common><point>
      <color>2 1 0.5</color>
      <constant_attenuation>1</constant_attenuation>
      <linear_attenuation>0.5</linear_attenuation>
      <quadratic_attenuation>0.25</quadratic_attenuation>
    </point></technique_common></light>
    <light id="spot" name="spot"><technique_common><spot>
      <color>1 1 1</color>
      <constant_attenuation>1</constant_attenuation>
      <linear_attenuation>0</linear_attenuation>
      <quadratic_attenuation>0</quadratic_attenuation>
      <falloff_angle>60</falloff_angle>
      <falloff_exponent>0</falloff_exponent>
    </spot></technique_common></light>
  </library_lights>
  <library_effects>
    <effect id="red-fx"><profile_COMMON><technique sid="common"><phong>
      <diffuse><color>0.8 0.1 0.1 1</color></diffuse>
      <specular><color>0.5 0.5 0.5 1</color></specular>
      <shininess><float>64</float></shininess>
    </phong></technique></profile_COMMON></effect>
  </library_effects>
  <library_materials>
    <material id="red" name="red"><instance_effect url="#red-fx"/></material>
  </library_materials>
  <library_geometries>
    <geometry id="tri" name="tri"><mesh>
      <source id="tri-pos">
        <float_array id="tri-pos-a" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#tri-pos-a" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <source id="tri-n">
        <float_array id="tri-n-a" count="3">0 0 1</float_array>
        <technique_common><accessor source="#tri-n-a" count="1" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="tri-v"><input semantic="POSITION" source="#tri-pos"/></vertices>
      <triangles material="mat" count="1">
        <input semantic="VERTEX" source="#tri-v" offset="0"/>
        <input semantic="NORMAL" source="#tri-n" offset="1"/>
        <p>0 0 1 0 2 0</p>
      </triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene" name="scene">
    <node id="parent" name="parent"><translate>10 0 0</translate>"""
      + tri_geometry.format(id="scaled", transform="<scale>2 2 2</scale>")
      + tri_geometry.format(id="mirrored", transform="<scale>-1 1 1</scale>") + """
    </node>
    <node id="lampnode" name="lampnode"><translate>0 5 0</translate>
      <instance_light url="#lamp"/></node>
    <node id="spotnode" name="spotnode"><translate>0 5 5</translate>
      <instance_light url="#spot"/></node>
    <node id="camnode" name="camnode"><translate>0 0 10</translate>
      <instance_camera url="#cam"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
""")

# glTF 1.0 (objects keyed by name, the asset's version a number as some exporters wrote it):
# a unit quad in z = 0 from (0, 0) to (1, 1), two triangles. tinygltf reads only 2.0, so
# gnomon hands it to assimp.
quad_bytes = (struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0) +
              struct.pack("<6H", 0, 1, 2, 0, 2, 3))
write("quad_gltf1.gltf", """
{
  "asset": {"version": 1},
  "buffers": {"data": {"byteLength": 60, "type": "arraybuffer",
    "uri": "data:application/octet-stream;base64,""" +
      __import__("base64").b64encode(quad_bytes).decode() + """"}},
  "bufferViews": {
    "positions": {"buffer": "data", "byteOffset": 0, "byteLength": 48, "target": 34962},
    "indices": {"buffer": "data", "byteOffset": 48, "byteLength": 12, "target": 34963}},
  "accessors": {
    "position": {"bufferView": "positions", "byteOffset": 0, "byteStride": 12,
      "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    "index": {"bufferView": "indices", "byteOffset": 0, "componentType": 5123, "count": 6,
      "type": "SCALAR"}},
  "materials": {"grey": {"values": {"diffuse": [0.5, 0.5, 0.5, 1]}}},
  "meshes": {"quad": {"primitives": [{"attributes": {"POSITION": "position"},
    "indices": "index", "material": "grey", "mode": 4}]}},
  "nodes": {"root": {"meshes": ["quad"]}},
  "scenes": {"main": {"nodes": ["root"]}},
  "scene": "main"
}
""")


# A Blitz3D .b3d with one triangle (0,0,0) (1,0,0) (0,1,0) and an animation whose last key
# (frame 4) lies past its clip's 3 frames, as Minetest's carts and characters have: assimp's
# validation refuses such a file unless the animation is dropped first.
def b3d_chunk(tag, data):
    return tag + struct.pack("<i", len(data)) + data


b3d_mesh = b3d_chunk(b"MESH", struct.pack("<i", -1) +
                     b3d_chunk(b"VRTS", struct.pack("<iii", 0, 0, 0) +
                               struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)) +
                     b3d_chunk(b"TRIS", struct.pack("<i", -1) + struct.pack("<3i", 0, 1, 2)))
b3d_keys = b3d_chunk(b"KEYS", struct.pack("<i", 1) + struct.pack("<i3f", 1, 0, 0, 0) +
                     struct.pack("<i3f", 4, 0, 0, 0))
b3d_node = b3d_chunk(b"NODE", b"root\0" + struct.pack("<3f3f4f", 0, 0, 0, 1, 1, 1, 1, 0, 0, 0) +
                     b3d_mesh + b3d_keys + b3d_chunk(b"ANIM", struct.pack("<iif", 0, 3, 30.0)))
with open(os.path.join(here, "anim_past_end.b3d"), "wb") as f:
    f.write(b3d_chunk(b"BB3D", struct.pack("<i", 1) + b3d_node))

# OpenGEX with a light object no light node uses: assimp gives the light no node and its
# validation refuses the file unless the light is dropped first.
write("orphan_light.ogex", """
Metric {float {1.0}}
GeometryNode $node1
{
    Name {string {"tri"}}
    ObjectRef {ref {$geometry1}}
}
LightObject $light1 (type = "point")
{
    Color (attrib = "light") {float[3] {{1.0, 1.0, 1.0}}}
}
GeometryObject $geometry1
{
    Mesh (primitive = "triangles")
    {
        VertexArray (attrib = "position") {float[3] {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}
        IndexArray {unsigned_int32[3] {{0, 1, 2}}}
    }
}
""")

# Binary glTF 1.0 (header version 1, one JSON content block): read by neither tinygltf nor
# Debian's assimp 5.2, refused with a sentence that says so.
glb1_json = b'{"asset": {"version": "1.0"}, "scene": "s", "scenes": {"s": {"nodes": []}}}'
with open(os.path.join(here, "binary_gltf1.glb"), "wb") as f:
    f.write(b"glTF" + struct.pack("<IIII", 1, 20 + len(glb1_json), len(glb1_json), 0) + glb1_json)
