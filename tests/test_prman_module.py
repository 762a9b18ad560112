"""tools/python/prman.py: a course script's Ri calls become the RIB RenderMan's prman module writes,
and Begin("__render") renders it with rixrender.

    python3 tests/test_prman_module.py path/to/rixrender
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools", "python"))
import prman  # noqa: E402

RIXRENDER = None


def spiral(data, detail):
    """A Python procedural, as course scripts pass to ri.Procedural: it writes its geometry itself."""
    ri, radius = data
    ri.Sphere(radius, -radius, radius, 360)


def write_scene(ri):
    ri.Option("rib", {"string asciistyle": "indented"})
    ri.ArchiveRecord(ri.COMMENT, "made by %s", "a test")
    ri.Display("scene.exr", "file", "rgba")
    ri.Format(32, 24, 1)
    ri.Projection(ri.PERSPECTIVE, {ri.FOV: 45})
    ri.ConcatTransform([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 6, 1]])
    ri.WorldBegin()
    light = ri.LightSource("pointlight", {"from": [0, 0, -4], "float intensity": 20})
    ri.Illuminate(light, 1)
    ri.AttributeBegin()
    ri.Bxdf("PxrDiffuse", "red", {"color diffuseColor": [1, 0, 0]})
    ri.Attribute("identifier", {"name": "ball"})
    ri.Procedural((ri, 0.5), [-1, 1, -1, 1, -1, 1], spiral, None)
    ri.AttributeEnd()
    shape = ri.ObjectBegin()
    ri.Hyperboloid([1, 0, 0.5], [1, 0, -0.5], 270)
    ri.ObjectEnd()
    ri.ObjectInstance(shape)
    ri.WorldEnd()


EXPECTED = """##RenderMan RIB
version 3.04
# made by a test
Display "scene.exr" "file" "rgba"
Format 32 24 1
Projection "perspective" "fov" [45]
ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 6 1]
WorldBegin
    LightSource "pointlight" "light1" "from" [0 0 -4] "float intensity" [20]
    Illuminate "light1" 1
    AttributeBegin
        Bxdf "PxrDiffuse" "red" "color diffuseColor" [1 0 0]
        Attribute "identifier" "name" ["ball"]
        AttributeBegin
            Sphere 0.5 -0.5 0.5 360
        AttributeEnd
    AttributeEnd
    ObjectBegin "object2"
        Hyperboloid 1 0 0.5 1 0 -0.5 270
    ObjectEnd
    ObjectInstance "object2"
WorldEnd
"""


class PrmanModule(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="prman-test-")
        self.previous = os.getcwd()
        os.chdir(self.folder)

    def tearDown(self):
        os.chdir(self.previous)
        shutil.rmtree(self.folder, ignore_errors=True)

    def test_ri_calls_write_the_rib_prman_writes(self):
        ri = prman.Ri()
        ri.Begin("scene.rib")
        write_scene(ri)
        ri.End()
        with open("scene.rib") as written:
            self.assertEqual(written.read(), EXPECTED)
        # ... and the renderer reads it, lit: the red ball and the hyperboloid are in view.
        rendered = subprocess.run([RIXRENDER, "--quiet", "--spp", "1", "scene.rib"], capture_output=True, text=True)
        self.assertEqual(rendered.returncode, 0, rendered.stderr)
        self.assertNotIn("warning", rendered.stderr)
        self.assertTrue(os.path.exists("scene.exr"))

    def test_render_target_renders_at_end_and_cleans_up(self):
        os.environ["RIXRENDER"] = RIXRENDER
        os.environ["RIXRENDER_ARGS"] = "--quiet --spp 1"
        for target in (prman.Ri().RENDER, "launch:prman? -ctrl $ctrlin $ctrlout"):
            ri = prman.Ri()
            ri.Begin(target)
            write_scene(ri)
            rib = ri._path
            ri.End()
            self.assertTrue(os.path.exists("scene.exr"), target)  # written where the script runs
            self.assertFalse(os.path.exists(os.path.dirname(rib)), target)  # the RIB rendered is gone
            self.assertEqual(os.listdir("."), ["scene.exr"], target)  # and no file named after the target
            os.remove("scene.exr")

    def test_a_failed_render_keeps_its_rib_and_says_where(self):
        os.environ["RIXRENDER"] = RIXRENDER
        os.environ["RIXRENDER_ARGS"] = "--quiet --spp 1"
        script = ("import prman\nri = prman.Ri()\nri.Begin('__render')\nri.WorldBegin()\n"
                  "ri.Sphere('one', -1, 1, 360)\nri.WorldEnd()\nri.End()\n")
        env = dict(os.environ, PYTHONPATH=os.path.dirname(prman.__file__))
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env)
        self.assertIn("scene.rib:4:12: Sphere: expected radius", run.stderr)
        kept = run.stderr.split("the RIB that was rendered is kept at ")[1].strip()
        self.assertTrue(os.path.exists(kept), run.stderr)
        shutil.rmtree(os.path.dirname(kept))

    def test_a_script_that_never_calls_end_is_told_nothing_was_rendered(self):
        script = ("import prman\nri = prman.Ri()\nri.Begin('__render')\nri.WorldBegin()\n"
                  "ri.Sphere(1, -1, 1, 360)\nri.WorldEnd()\n")
        env = dict(os.environ, PYTHONPATH=os.path.dirname(prman.__file__), RIXRENDER=RIXRENDER)
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("was never closed by ri.End(), so nothing was rendered", run.stderr)
        kept = run.stderr.split("(the RIB written is at ")[1].split(")")[0]
        with open(kept) as written:
            self.assertIn("Sphere 1 -1 1 360", written.read())
        shutil.rmtree(os.path.dirname(kept))
        # A script that does call End hears nothing of the kind.
        run = subprocess.run([sys.executable, "-c", script.replace("__render", "ended.rib") + "ri.End()\n"],
                             capture_output=True, text=True, env=env)
        self.assertEqual(run.stderr, "")

    def test_relative_search_paths_are_the_scripts_folders(self):
        # The RIB rendered sits in a folder of its own; the script's "./assets/" and
        # "./textures/" are beside the script, where RenderMan looks for them.
        os.makedirs("assets")
        os.makedirs("textures")
        with open(os.path.join("assets", "ball.rib"), "w") as archive:
            archive.write('Sphere 1 -1 1 360\n')
        made = subprocess.run([shutil.which("oiiotool"), "--pattern", "constant:color=1,0,0", "8x8", "3",
                               "-o", os.path.join("textures", "red.exr")], capture_output=True, text=True)
        self.assertEqual(made.returncode, 0, made.stderr)
        script = ("import prman\nri = prman.Ri()\nri.Begin('__render')\n"
                  "ri.Option('searchpath', {'string archive': './assets/:@', 'string texture': './textures/:@'})\n"
                  "ri.Display('found.exr', 'file', 'rgba')\nri.Format(16, 16, 1)\n"
                  "ri.Projection(ri.PERSPECTIVE, {ri.FOV: 30})\nri.WorldBegin()\nri.Translate(0, 0, 5)\n"
                  "ri.Pattern('PxrTexture', 'tex', {'string filename': 'red.exr'})\n"
                  "ri.Bxdf('PxrConstant', 'c', {'reference color emitColor': ['tex:resultRGB']})\n"
                  "ri.ReadArchive('ball.rib')\nri.WorldEnd()\nri.End()\n")
        env = dict(os.environ, PYTHONPATH=os.path.dirname(prman.__file__), RIXRENDER=RIXRENDER,
                   RIXRENDER_ARGS="--spp 1")
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertNotIn("not found", run.stderr)
        self.assertNotIn("does not exist", run.stderr)
        # The ball fills the middle of the image with the texture's red.
        centre = subprocess.run([shutil.which("oiiotool"), "found.exr", "--cut", "2x2+7+7", "--printstats"],
                                capture_output=True, text=True)
        self.assertIn("Stats Avg: 1.000000 0.000000 0.000000 1.000000", centre.stdout, centre.stdout)

    def test_procedural2_writes_the_names_renderman_reads(self):
        with open("ball.rib", "w") as archive:
            archive.write("Sphere 1 -1 1 360\n")
        ri = prman.Ri()
        ri.Begin("delayed.rib")
        ri.WorldBegin()
        ri.Procedural2(ri.Proc2DelayedReadArchive, ri.SimpleBound,
                       {"string filename": ["ball.rib"], "float[6] __bound": [-1, 1, -1, 1, -1, 1]})
        ri.WorldEnd()
        ri.End()
        with open("delayed.rib") as written:
            self.assertIn('Procedural2 "DelayedReadArchive2" "SimpleBound" "string filename" ["ball.rib"]',
                          written.read())
        rendered = subprocess.run([RIXRENDER, "--spp", "1", "delayed.rib"], capture_output=True, text=True)
        self.assertEqual(rendered.returncode, 0, rendered.stderr)
        self.assertNotIn("warning", rendered.stderr)
        hits = re.search(r"rays: \d+ camera, (\d+) shadow", rendered.stderr)  # a shadow ray from each hit
        self.assertTrue(hits and int(hits.group(1)) > 0, rendered.stderr)  # the archive's ball was read

    def test_calls_outside_begin_and_values_of_no_rib_type_are_errors(self):
        ri = prman.Ri()
        with self.assertRaisesRegex(prman.Error, "before ri.Begin"):
            ri.Sphere(1, -1, 1, 360)
        ri.Begin("bad.rib")
        with self.assertRaisesRegex(prman.Error, "is not a RIB value"):
            ri.Translate(object(), 0, 0)
        ri.End()


if __name__ == "__main__":
    RIXRENDER = os.path.abspath(sys.argv.pop(1))
    unittest.main()
