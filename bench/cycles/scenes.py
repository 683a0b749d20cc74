"""The four scenes of the rts-vs-Cycles comparison, described once and written two ways.

Run with plain python3 it writes each scene as an .rts file:
    python3 bench/cycles/scenes.py OUTDIR
Run inside Blender it builds the scene for Cycles with the fair settings of issue 19 and
renders it to a linear float image:
    blender -b --factory-startup -P bench/cycles/scenes.py -- SCENE OUT.pfm SAMPLES SEED THREADS
and prints `cycles_render_seconds W CPU` (wall and process CPU time of the render call alone,
Blender's start-up excluded).

Coordinates are rts's (left-handed, +y up, +z into the picture). Blender is right-handed and
+z up; (x, y, z) in rts is (x, z, y) in Blender, a mirror that turns one handedness into the
other, so the same camera sees the same picture.
"""
import math
import os
import struct
import sys

SIZE = int(os.environ.get("RTS_CYCLES_SIZE", "128"))  # the stored test references are smaller

# Materials: kind and its parameters. 'diffuse' albedo; 'emit' radiance on a diffuse surface;
# 'glass' dielectric, smooth or (a third value) GGX-rough with alpha = roughness; 'metal' GGX
# conductor of constant reflectance, alpha = roughness.
MATERIALS = {
    'white': ('diffuse', (0.73, 0.73, 0.73)),
    'red': ('diffuse', (0.65, 0.05, 0.05)),
    'green': ('diffuse', (0.12, 0.45, 0.15)),
    'lamp': ('emit', (0.78, 0.78, 0.78), (17.0, 12.0, 4.0)),
    'floor': ('diffuse', (0.8, 0.78, 0.74)),
    'wall': ('diffuse', (0.55, 0.6, 0.65)),
    'softbox': ('emit', (0.0, 0.0, 0.0), (12.0, 12.0, 12.0)),
    'glass': ('glass', 1.5),
    'frosted': ('glass', 1.5, 0.3),
    'gold': ('metal', (1.0, 0.78, 0.34), 0.3),
    'grey': ('diffuse', (0.5, 0.5, 0.5)),
    # A medium in a clear container (no surface): scattering and absorption per unit length,
    # and the Henyey-Greenstein mean cosine.
    'smoke': ('medium', (1.6, 1.6, 1.6), (0.15, 0.35, 0.7), 0.4),
    'lamp_ball': ('emit', (0.0, 0.0, 0.0), (40.0, 36.0, 30.0)),
}


def cornell():
    q = []
    q.append(('quad', (-1, 0, -1), (2, 0, 0), (0, 0, 2), 'white'))  # floor
    q.append(('quad', (-1, 2, -1), (2, 0, 0), (0, 0, 0.8), 'white'))  # ceiling around the lamp
    q.append(('quad', (-1, 2, 0.2), (2, 0, 0), (0, 0, 0.8), 'white'))
    q.append(('quad', (-1, 2, -0.2), (0.75, 0, 0), (0, 0, 0.4), 'white'))
    q.append(('quad', (0.25, 2, -0.2), (0.75, 0, 0), (0, 0, 0.4), 'white'))
    q.append(('quad', (-1, 0, 1), (2, 0, 0), (0, 2, 0), 'white'))  # back
    q.append(('quad', (-1, 0, -1), (0, 0, 2), (0, 2, 0), 'red'))  # left
    q.append(('quad', (1, 0, -1), (0, 0, 2), (0, 2, 0), 'green'))  # right
    q.append(('quad', (-0.25, 2, -0.2), (0.5, 0, 0), (0, 0, 0.4), 'lamp'))
    q.append(('box', (-0.3, 0, -0.3), (0.3, 0.6, 0.3), -18, (0.35, 0, -0.3), 'white'))
    q.append(('box', (-0.3, 0, -0.3), (0.3, 1.2, 0.3), 17, (-0.35, 0, 0.35), 'white'))
    return dict(camera=((0, 1, -3.4), (0, 1, 0), 40), depth=8, objects=q)


def room(extra):
    """A floor, a back wall and a softbox up to the left: the stage of the glass and metal scenes."""
    q = [('quad', (-4, 0, -4), (8, 0, 0), (0, 0, 8), 'floor'),
         ('quad', (-4, 0, 2), (8, 0, 0), (0, 4, 0), 'wall'),
         ('quad', (-2.2, 3, -1.2), (1.2, 0, 0), (0, 0, 1.2), 'softbox')]
    return q + extra


def caustic():
    return dict(camera=((0, 1.6, -3.2), (0, 0.5, 0), 40), depth=10,
                objects=room([('sphere', (0, 0.6, 0), 0.6, 'glass')]))


def rough_metal():
    return dict(camera=((0, 1.6, -3.2), (0, 0.5, 0), 40), depth=8,
                objects=room([('sphere', (0, 0.6, 0), 0.6, 'gold')]))


def rough_glass():
    return dict(camera=((0, 1.6, -3.2), (0, 0.5, 0), 40), depth=10,
                objects=room([('sphere', (0, 0.6, 0), 0.6, 'frosted')]))


def env_lit():
    return dict(camera=((0, 1.2, -3.2), (0, 0.5, 0), 45), depth=8, env='env.hdr',
                objects=[('quad', (-3, 0, -3), (6, 0, 0), (0, 0, 6), 'grey'),
                         ('sphere', (-0.7, 0.6, 0), 0.6, 'white'),
                         ('sphere', (0.7, 0.6, 0.2), 0.6, 'gold')])


def smoke():
    """A ball of scattering, tinted smoke on the floor of the room, lit by the softbox (issue 23)."""
    return dict(camera=((0, 1.6, -3.2), (0, 0.5, 0), 40), depth=8,
                objects=room([('sphere', (0, 0.7, 0), 0.7, 'smoke')]))


def smoke_lamp():
    """The smoke ball alone in the dark, lit by a small glowing ball out of view: the stored Cycles reference
    of tests/render/test_media.cpp (no walls, whose lighting the two engines differ on)."""
    return dict(camera=((0, 1.0, -3.2), (0, 0.7, 0), 40), depth=8,
                objects=[('sphere', (0, 0.7, 0), 0.7, 'smoke'), ('sphere', (-1.6, 2.0, -0.3), 0.25, 'lamp_ball')])


SCENES = {'cornell': cornell, 'caustic': caustic, 'rough_metal': rough_metal, 'env_lit': env_lit,
          'rough_glass': rough_glass, 'smoke': smoke, 'smoke_lamp': smoke_lamp}


# The environment: a sky gradient and a small bright sun, as a flat (uncompressed) Radiance .hdr
# that stb (rts) and Blender both read. rts's latitude-longitude lookup is
# u = 0.5 + atan2(x, z) / 2pi, Blender's u = 0.5 - atan2(y_b, x_b) / 2pi = u_rts - 0.25 under the
# axis swap, so Blender's copy is the same file rolled a quarter turn.
ENV_W, ENV_H = 256, 128


def env_pixels():
    sun_dir = (0.5, 0.6, -0.4)  # rts coordinates: up, to the right, towards the camera
    n = math.sqrt(sum(c * c for c in sun_dir))
    sun_dir = tuple(c / n for c in sun_dir)
    rows = []
    for j in range(ENV_H):
        v = 1.0 - (j + 0.5) / ENV_H
        lat = (v - 0.5) * math.pi
        row = []
        for i in range(ENV_W):
            u = (i + 0.5) / ENV_W
            phi = (u - 0.5) * 2 * math.pi
            d = (math.cos(lat) * math.sin(phi), math.sin(lat), math.cos(lat) * math.cos(phi))
            cos_sun = sum(a * b for a, b in zip(d, sun_dir))
            if lat > 0:
                c = (0.35 + 0.25 * (1 - lat / (math.pi / 2)), 0.55, 0.9)
            else:
                c = (0.25, 0.22, 0.2)
            if cos_sun > math.cos(math.radians(6)):
                c = (60.0, 55.0, 45.0)
            row.append(c)
        rows.append(row)
    return rows


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    f, e = math.frexp(m)
    s = f * 256.0 / m
    return bytes((int(c[0] * s), int(c[1] * s), int(c[2] * s), e + 128))


def write_hdr(path, roll=0):
    rows = env_pixels()
    with open(path, 'wb') as f:
        f.write(b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n')
        f.write(('-Y %d +X %d\n' % (ENV_H, ENV_W)).encode())
        for row in rows:
            row = row[roll:] + row[:roll]
            f.write(b''.join(rgbe(c) for c in row))


# ---------------------------------------------------------------------------------------------
# rts writer


def rts_vec(v):
    return '<%s>' % ', '.join('%g' % c for c in v)


def rts_rgb(c):
    return 'rgb(%s)' % ', '.join('%g' % x for x in c)


def rts_material(name):
    m = MATERIALS[name]
    if m[0] == 'diffuse':
        return 'material { color = %s  diffuse = 1  specular = 0 }' % rts_rgb(m[1])
    if m[0] == 'emit':
        return 'material { color = %s  diffuse = 1  specular = 0  emission = %s }' % (rts_rgb(m[1]), rts_rgb(m[2]))
    if m[0] == 'glass':
        rough = '  roughness = %g' % m[2] if len(m) > 2 else ''
        return 'material { color = rgb(1)  diffuse = 0  specular = 0  transmit = 1  ior = %g%s }' % (m[1], rough)
    if m[0] == 'metal':
        return ('material { color = rgb(0)  diffuse = 0  specular = 0  reflect = %s  roughness = %g }'
                % (rts_rgb(m[1]), m[2]))
    if m[0] == 'medium':
        return ('material { transmit = 1  ior = 1  diffuse = 0  media_scattering = %s  media_absorption = %s  '
                'media_eccentricity = %g }' % (rts_rgb(m[1]), rts_rgb(m[2]), m[3]))
    raise ValueError(name)


def rts_scene(name, samples=64):
    s = SCENES[name]()
    pos, look, fov = s['camera']
    out = ['// Generated by bench/cycles/scenes.py: the %s scene of the Cycles comparison.' % name]
    env = ''
    if s.get('env'):
        env = '  environment = latlong_map { file = "%s" }' % s['env']
    out.append('settings { width = %d  height = %d  samples = %d  max_depth = %d  integrator = "path"%s }'
               % (SIZE, SIZE, samples, s['depth'], env))
    out.append('camera { position = %s  look_at = %s  fov = %g }' % (rts_vec(pos), rts_vec(look), fov))
    for o in s['objects']:
        if o[0] == 'quad':
            out.append('quad { corner = %s  edge_u = %s  edge_v = %s  material = %s }'
                       % (rts_vec(o[1]), rts_vec(o[2]), rts_vec(o[3]), rts_material(o[4])))
        elif o[0] == 'box':
            out.append('box { min = %s  max = %s  material = %s } rotate <0, %g, 0> translate %s'
                       % (rts_vec(o[1]), rts_vec(o[2]), rts_material(o[5]), o[3], rts_vec(o[4])))
        elif o[0] == 'sphere':
            out.append('sphere { center = %s  radius = %g  material = %s }'
                       % (rts_vec(o[1]), o[2], rts_material(o[3])))
    return '\n'.join(out) + '\n'


# ---------------------------------------------------------------------------------------------
# Blender writer


def to_blender(v):
    return (v[0], v[2], v[1])


def rotate_y(p, deg):
    """glm::rotate about +y, as rts applies `rotate <0, deg, 0>`."""
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    return (c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2])


def blender_material(bpy, name, cache={}):
    if name in cache:
        return cache[name]
    m = MATERIALS[name]
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new('ShaderNodeOutputMaterial')
    if m[0] == 'diffuse':
        b = nt.nodes.new('ShaderNodeBsdfDiffuse')
        b.inputs['Color'].default_value = (*m[1], 1)
        b.inputs['Roughness'].default_value = 0.0  # Lambert, not Oren-Nayar
        nt.links.new(b.outputs[0], out.inputs['Surface'])
    elif m[0] == 'emit':
        b = nt.nodes.new('ShaderNodeBsdfDiffuse')
        b.inputs['Color'].default_value = (*m[1], 1)
        b.inputs['Roughness'].default_value = 0.0
        e = nt.nodes.new('ShaderNodeEmission')
        e.inputs['Color'].default_value = (*m[2], 1)
        e.inputs['Strength'].default_value = 1.0  # radiance = colour x strength
        add = nt.nodes.new('ShaderNodeAddShader')
        nt.links.new(b.outputs[0], add.inputs[0])
        nt.links.new(e.outputs[0], add.inputs[1])
        nt.links.new(add.outputs[0], out.inputs['Surface'])
    elif m[0] == 'glass':
        b = nt.nodes.new('ShaderNodeBsdfGlass')
        b.distribution = 'GGX' if len(m) > 2 else 'SHARP'
        if len(m) > 2:
            b.inputs['Roughness'].default_value = math.sqrt(m[2])  # alpha = r^2, as for metal
        b.inputs['Color'].default_value = (1, 1, 1, 1)
        b.inputs['IOR'].default_value = m[1]
        nt.links.new(b.outputs[0], out.inputs['Surface'])
    elif m[0] == 'medium':
        # No surface shader: the boundary lets light through unchanged. Cycles' Volume Scatter
        # scatters color x density per unit length; Volume Absorption absorbs (1 - color) x
        # density (svm_node_closure_volume), so colour = 1 - sigma_a / density.
        sigma_s, sigma_a, g = m[1], m[2], m[3]
        ds, da = max(sigma_s), max(sigma_a)
        sc = nt.nodes.new('ShaderNodeVolumeScatter')
        sc.inputs['Color'].default_value = (*[c / ds for c in sigma_s], 1)
        sc.inputs['Density'].default_value = ds
        sc.inputs['Anisotropy'].default_value = g
        ab = nt.nodes.new('ShaderNodeVolumeAbsorption')
        ab.inputs['Color'].default_value = (*[1 - c / da for c in sigma_a], 1)
        ab.inputs['Density'].default_value = da
        add = nt.nodes.new('ShaderNodeAddShader')
        nt.links.new(sc.outputs[0], add.inputs[0])
        nt.links.new(ab.outputs[0], add.inputs[1])
        nt.links.new(add.outputs[0], out.inputs['Volume'])
        mat.cycles.homogeneous_volume = True  # exact distance sampling, no ray marching
    elif m[0] == 'metal':
        b = nt.nodes.new('ShaderNodeBsdfGlossy')
        b.distribution = 'GGX'  # single scattering, as rts
        b.inputs['Color'].default_value = (*m[1], 1)
        b.inputs['Roughness'].default_value = math.sqrt(m[2])  # Cycles squares its roughness: alpha = r^2
        nt.links.new(b.outputs[0], out.inputs['Surface'])
    cache[name] = mat
    return mat


def blender_mesh(bpy, name, verts, faces, mat, smooth=False):
    me = bpy.data.meshes.new(name)
    me.from_pydata([to_blender(v) for v in verts], [], faces)
    me.update()
    if smooth:
        for p in me.polygons:
            p.use_smooth = True
    me.materials.append(mat)
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def build_blender(bpy, name, samples, seed, threads, env_path):
    import mathutils
    s = SCENES[name]()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = 'CYCLES'
    c = scene.cycles
    c.device = 'CPU'
    c.samples = samples
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    d = s['depth']
    c.max_bounces = d
    c.diffuse_bounces = d
    c.glossy_bounces = d
    c.transmission_bounces = d
    c.volume_bounces = d  # only the smoke scene has a volume
    c.transparent_max_bounces = d
    c.seed = seed
    # rts averages each pixel's samples uniformly over the pixel (a box of width 1): the same
    # footprint, where Cycles' default 1.5-wide Blackman-Harris would blur the edges.
    c.pixel_filter_type = 'BOX'
    c.filter_width = 1.0
    scene.render.threads_mode = 'FIXED'
    scene.render.threads = threads
    scene.render.resolution_x = SIZE
    scene.render.resolution_y = SIZE
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = 'Standard'
    scene.view_settings.look = 'None'
    scene.view_settings.exposure = 0
    scene.view_settings.gamma = 1
    scene.render.image_settings.file_format = 'OPEN_EXR'
    scene.render.image_settings.color_depth = '32'
    scene.render.image_settings.exr_codec = 'NONE'

    world = bpy.data.worlds.new('world')
    scene.world = world
    world.use_nodes = True
    bg = world.node_tree.nodes['Background']
    bg.inputs['Strength'].default_value = 1.0
    if s.get('env'):
        tex = world.node_tree.nodes.new('ShaderNodeTexEnvironment')
        tex.image = bpy.data.images.load(env_path)
        tex.image.colorspace_settings.name = 'Linear'
        tex.interpolation = 'Linear'  # rts's latlong_map default: bilinear
        world.node_tree.links.new(tex.outputs['Color'], bg.inputs['Color'])
        world.cycles.sampling_method = 'MANUAL'
        world.cycles.sample_map_resolution = 256
    else:
        bg.inputs['Color'].default_value = (0, 0, 0, 1)

    for k, o in enumerate(s['objects']):
        if o[0] == 'quad':
            p, eu, ev = o[1], o[2], o[3]
            v = [p, tuple(a + b for a, b in zip(p, eu)),
                 tuple(a + b + e for a, b, e in zip(p, eu, ev)), tuple(a + e for a, e in zip(p, ev))]
            blender_mesh(bpy, 'quad%d' % k, v, [(0, 1, 2, 3)], blender_material(bpy, o[4]))
        elif o[0] == 'box':
            lo, hi, deg, t = o[1], o[2], o[3], o[4]
            v = []
            for i in range(8):
                p = (hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2])
                p = rotate_y(p, deg)
                v.append(tuple(a + b for a, b in zip(p, t)))
            faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
            blender_mesh(bpy, 'box%d' % k, v, faces, blender_material(bpy, o[5]))
        elif o[0] == 'sphere':
            # A finely tessellated, smooth-shaded UV sphere (Cycles 3.4 has no analytic sphere).
            ctr, r = o[1], o[2]
            nu, nv = 256, 128
            v = [(ctr[0], ctr[1] + r, ctr[2])]
            for j in range(1, nv):
                th = math.pi * j / nv
                for i in range(nu):
                    ph = 2 * math.pi * i / nu
                    v.append((ctr[0] + r * math.sin(th) * math.cos(ph), ctr[1] + r * math.cos(th),
                              ctr[2] + r * math.sin(th) * math.sin(ph)))
            v.append((ctr[0], ctr[1] - r, ctr[2]))
            faces = []
            for i in range(nu):
                faces.append((0, 1 + i, 1 + (i + 1) % nu))
            for j in range(nv - 2):
                for i in range(nu):
                    a = 1 + j * nu + i
                    b = 1 + j * nu + (i + 1) % nu
                    faces.append((a, a + nu, b + nu, b))
            last = len(v) - 1
            base = 1 + (nv - 2) * nu
            for i in range(nu):
                faces.append((base + i, last, base + (i + 1) % nu))
            blender_mesh(bpy, 'sphere%d' % k, v, faces, blender_material(bpy, o[3]), smooth=True)

    pos, look, fov = s['camera']
    cam_data = bpy.data.cameras.new('cam')
    cam_data.sensor_fit = 'HORIZONTAL'
    cam_data.angle = math.radians(fov)  # rts's fov is horizontal
    cam = bpy.data.objects.new('cam', cam_data)
    scene.collection.objects.link(cam)
    cam.location = to_blender(pos)
    direction = mathutils.Vector(to_blender(look)) - mathutils.Vector(to_blender(pos))
    cam.rotation_euler = direction.to_track_quat('-Z', 'Y').to_euler()
    scene.camera = cam
    return scene


def exr_to_pfm(bpy, exr, pfm):
    img = bpy.data.images.load(exr)
    w, h = img.size
    px = list(img.pixels[:])  # RGBA floats, bottom row first: PFM's order too
    with open(pfm, 'wb') as f:
        f.write(b'PF\n%d %d\n-1.0\n' % (w, h))
        data = []
        for i in range(w * h):
            data.extend(px[4 * i:4 * i + 3])
        f.write(struct.pack('<%df' % len(data), *data))


def blender_main(argv):
    import time
    import bpy
    name, out_pfm, samples, seed, threads = argv[0], argv[1], int(argv[2]), int(argv[3]), int(argv[4])
    env_path = os.path.abspath(os.path.join(os.path.dirname(out_pfm) or '.', 'env_blender.hdr'))
    if SCENES[name]().get('env'):
        write_hdr(env_path, roll=ENV_W // 4)
    scene = build_blender(bpy, name, samples, seed, threads, env_path)
    exr = os.path.abspath(out_pfm) + '.exr'
    scene.render.filepath = exr
    w0, c0 = time.perf_counter(), time.process_time()
    bpy.ops.render.render(write_still=True)
    w1, c1 = time.perf_counter(), time.process_time()
    print('cycles_render_seconds %.3f %.3f' % (w1 - w0, c1 - c0))
    exr_to_pfm(bpy, exr, out_pfm)
    os.remove(exr)


if __name__ == '__main__':
    if '--' in sys.argv:  # inside Blender
        blender_main(sys.argv[sys.argv.index('--') + 1:])
    else:
        outdir = sys.argv[1]
        os.makedirs(outdir, exist_ok=True)
        write_hdr(os.path.join(outdir, 'env.hdr'))
        for n in SCENES:
            with open(os.path.join(outdir, n + '.rts'), 'w') as f:
                f.write(rts_scene(n))
