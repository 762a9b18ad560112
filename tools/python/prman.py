"""prman: the Python interface to RenderMan (RenderMan's `prman` module), as this renderer offers it.

Course scripts build their scenes with it:

    import prman
    ri = prman.Ri()
    ri.Begin("__render")            # or ri.Begin("scene.rib") to write a RIB file
    ri.Display("hello.exr", "it", "rgba")
    ri.Projection(ri.PERSPECTIVE, {ri.FOV: 45})
    ri.WorldBegin()
    ri.Translate(0, 0, 2)
    ri.Sphere(1, -1, 1, 360)
    ri.WorldEnd()
    ri.End()

Every Ri call writes its RIB request: positional arguments in order, then the parameter list given
as a dict ({"color diffuseColor": [1, 0, 0]}). Begin("__render") (ri.RENDER) renders what was written
with rixrender at End(). Run a script with this folder on PYTHONPATH:

    PYTHONPATH=/path/to/bxdflab/tools/python python3 scene.py

rixrender is the one named by $RIXRENDER, else the one built beside this folder
(build/bin/rixrender), else the one on PATH; $RIXRENDER_ARGS adds options to it
(RIXRENDER_ARGS="--spp 4 --resolution-scale 0.5" for a quick look).
"""

import atexit
import numbers
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

__all__ = ["Ri", "Init", "Cleanup", "RicGetProgress", "Error"]


class Error(Exception):
    """A call the interface cannot turn into RIB (a call outside Begin/End, an argument of no RIB type)."""


def _find_rixrender():
    named = os.environ.get("RIXRENDER")
    if named:
        return named
    built = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin", "rixrender")
    if os.access(built, os.X_OK):
        return os.path.normpath(built)
    on_path = shutil.which("rixrender")
    if on_path:
        return on_path
    raise Error("rixrender not found: set RIXRENDER, build the project (build/bin/rixrender) or put it on PATH")


def _number(value):
    if isinstance(value, bool) or isinstance(value, numbers.Integral):
        return str(int(value))
    return "%.9g" % float(value)  # every digit a float of the renderer keeps


def _string(value):
    return '"' + str(value).replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def _flatten(values):
    """The items of nested lists and tuples (a matrix given as rows, points given as triples), in order."""
    for value in values:
        if isinstance(value, (list, tuple)):
            yield from _flatten(value)
        elif hasattr(value, "tolist"):  # a numpy array, or a matrix class that gives its list
            yield from _flatten(value.tolist())
        else:
            yield value


def _value(value):
    """One argument as RIB: a string, a number, or an array of either."""
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, numbers.Number):
        return _number(value)
    if isinstance(value, (list, tuple)) or hasattr(value, "tolist"):
        items = list(_flatten([value]))
        return "[" + " ".join(_string(v) if isinstance(v, str) else _number(v) for v in items) + "]"
    raise Error("%r is not a RIB value (a string, a number or a list of them)" % (value,))


def _parameters(params):
    """A parameter list: each name quoted, each value an array (a single value is a list of one)."""
    words = []
    for name, value in params.items():
        words.append(_string(name))
        words.append(_value(value if isinstance(value, (list, tuple)) or hasattr(value, "tolist") else [value]))
    return words


# The interface's tokens: what each constant of prman.Ri stands for in RIB.
_TOKENS = {
    "RENDER": "__render",
    "PERSPECTIVE": "perspective", "ORTHOGRAPHIC": "orthographic",
    "FOV": "fov", "P": "P", "PW": "Pw", "PZ": "Pz", "N": "N", "NP": "Np", "CS": "Cs", "OS": "Os", "S": "s",
    "T": "t", "ST": "st", "WIDTH": "width", "CONSTANTWIDTH": "constantwidth",
    "HANDLEID": "__handleid", "COMMENT": "comment", "STRUCTURE": "structure", "VERBATIM": "verbatim",
    "BOXFILTER": "box", "GAUSSIAN": "gaussian", "GAUSSIANFILTER": "gaussian", "TRIANGLE": "triangle",
    "CATMULLROM": "catmull-rom", "SINC": "sinc", "SEPARABLECATMULLROM": "separable-catmull-rom",
    "BOX": "box", "BSPLINE": "b-spline",
    "CREASE": "crease", "CORNER": "corner", "HOLE": "hole", "INTERPOLATEBOUNDARY": "interpolateboundary",
    "INTERPBOUNDARY": "interpolateboundary",
    "FACEVARYINGINTERPOLATEBOUNDARY": "facevaryinginterpolateboundary",
    "COORDINATESYSTEM": "coordinatesystem", "INTENSITY": "intensity", "LIGHTCOLOR": "lightcolor",
    "FROM": "from", "TO": "to", "CONEANGLE": "coneangle", "CONEDELTAANGLE": "conedeltaangle",
    "KA": "Ka", "KD": "Kd", "KS": "Ks", "ROUGHNESS": "roughness", "SPECULARCOLOR": "specularcolor",
    "TEXTURENAME": "texturename", "FILE": "file", "FRAMEBUFFER": "framebuffer", "RGB": "rgb", "RGBA": "rgba",
    "Z": "z", "A": "a", "CUBIC": "cubic", "LINEAR": "linear", "PERIODIC": "periodic", "NONPERIODIC": "nonperiodic",
    "BILINEAR": "bilinear", "BICUBIC": "bicubic", "PRIMITIVE": "primitive", "UNION": "union",
    "INTERSECTION": "intersection", "DIFFERENCE": "difference", "INSIDE": "inside", "OUTSIDE": "outside",
    "LH": "lh", "RH": "rh", "NAME": "name", "SimpleBound": "SimpleBound",
    "Proc2DelayedReadArchive": "DelayedReadArchive2", "ProcDelayedReadArchive": "DelayedReadArchive",
    "Proc2DynamicLoad": "DynamicLoad",
    "ProcRunProgram": "RunProgram", "ProcDynamicLoad": "DynamicLoad", "ProcFree": None,
    "PRMAN_VERSION_STR": "24.0",  # the RenderMan whose RIB this renderer reads
}


class Ri:
    """RenderMan's interface: each call writes one RIB request between Begin and End."""

    def __init__(self):
        self._out = None
        self._target = None
        self._handles = 0
        self._indent = 0

    def __getattr__(self, name):
        if name in _TOKENS:
            return _TOKENS[name]
        if name[:1].isupper():
            return lambda *args: self._request(name, args)
        raise AttributeError("prman.Ri has no %r" % name)

    # Begin and End: where the RIB goes.

    def Begin(self, name="__render"):
        """Starts a RIB stream: to the file `name`, or, for "__render" (ri.RENDER), to a render at End().
        "launch:prman? ..." (RenderMan's renderer in a process of its own) renders at End() too."""
        if self._out is not None:
            raise Error("Begin inside Begin: call End first")
        self._target = "__render" if not name or name.startswith("launch:") else name
        if self._target == "__render":
            # Named after the script, so that a message about a line of it says whose RIB it is.
            script = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0].endswith(".py") else "scene.py"
            self._folder = tempfile.mkdtemp(prefix="prman-")
            self._path = os.path.join(self._folder, script[:-3] + ".rib")
        else:
            self._path = self._target
        self._out = open(self._path, "w")
        self._out.write("##RenderMan RIB\nversion 3.04\n")
        atexit.register(self._say_if_unended)

    def _say_if_unended(self):
        # A script that never calls End renders nothing, in RenderMan too; say so rather than end silently.
        if self._out is None:
            return
        self._out.close()
        self._out = None
        if self._target == "__render":
            sys.stderr.write("prman: ri.Begin(\"__render\") was never closed by ri.End(), so nothing was rendered "
                             "(the RIB written is at %s)\n" % self._path)
        else:
            sys.stderr.write("prman: ri.Begin(\"%s\") was never closed by ri.End(); the file holds the calls "
                             "made before the script ended\n" % self._path)

    def End(self):
        """Ends the stream; for "__render", renders it with rixrender from the current folder."""
        if self._out is None:
            raise Error("End without Begin")
        self._out.close()
        self._out = None
        atexit.unregister(self._say_if_unended)
        if self._target != "__render":
            return
        options = shlex.split(os.environ.get("RIXRENDER_ARGS", ""))
        result = subprocess.run([_find_rixrender()] + options + [self._path])
        if result.returncode == 0:
            shutil.rmtree(self._folder, ignore_errors=True)
        else:  # the RIB stays, so that the line an error names can be read
            sys.stderr.write("prman: the RIB that was rendered is kept at %s\n" % self._path)

    # Requests whose RIB is not their arguments in order.

    def ArchiveRecord(self, kind, text, *args):
        """A comment ("# text") or, for ri.VERBATIM, text written as it is."""
        text = text % args if args else text
        if kind == "verbatim":
            self._write(text)
        else:
            self._write("# " + text if kind == "comment" else "## " + text)

    def ObjectBegin(self, *args):
        """Starts a retained object and returns its handle, for ObjectInstance."""
        if args:
            handle = args[0]
        else:
            self._handles += 1
            handle = "object%d" % self._handles
        self._request("ObjectBegin", (handle,))
        return handle

    def LightSource(self, name, params=None):
        """A classic light; its handle is the parameter ri.HANDLEID, and it is returned for Illuminate."""
        return self._light("LightSource", name, params)

    def AreaLightSource(self, name, params=None):
        return self._light("AreaLightSource", name, params)

    def ReadArchive(self, name, callback=None, params=None):
        """Reads an archive (the callback of the C interface is not used)."""
        self._request("ReadArchive", (name,) + ((params,) if params else ()))

    def Procedural(self, data, bound, subdivide=None, free=None):
        """Procedural(["program", "arguments"], bound, ri.ProcRunProgram), in the C interface's order; a
        Python function as `subdivide` is called at once as subdivide(data, detail), inside an attribute
        block, and writes the procedural's geometry itself."""
        if callable(subdivide):
            self._request("AttributeBegin", ())
            subdivide(data, 1.0e30)  # the greatest detail: the geometry is made once, for any view
            self._request("AttributeEnd", ())
            return
        self._request("Procedural", (subdivide or "DelayedReadArchive", list(data), list(bound)))

    def Procedural2(self, subdivide, bound, params=None):
        self._request("Procedural2", (subdivide, bound) + ((params,) if params else ()))

    def Transform(self, matrix):
        self._request("Transform", (list(_flatten([matrix])),))

    def ConcatTransform(self, matrix):
        self._request("ConcatTransform", (list(_flatten([matrix])),))

    def Hyperboloid(self, point1, point2, thetamax, params=None):
        """Hyperboloid([x1, y1, z1], [x2, y2, z2], thetamax): RIB gives the points' numbers one by one."""
        self._request("Hyperboloid", tuple(_flatten([point1, point2])) + (thetamax,) + ((params,) if params else ()))

    def Color(self, *rgb):
        self._request("Color", (list(_flatten([rgb])),))

    def Opacity(self, *rgb):
        self._request("Opacity", (list(_flatten([rgb])),))

    def Option(self, name, params=None):
        if name == "rib":  # how the RIB is written (asciistyle, format): every RIB here is ASCII
            return
        self._request("Option", (name,) + ((params,) if params else ()))

    # Writing.

    def _light(self, request, name, params):
        params = dict(params or {})
        handle = params.pop("__handleid", None)
        if handle is None:
            self._handles += 1
            handle = "light%d" % self._handles
        self._request(request, (name, handle, params))
        return handle

    def _request(self, name, args):
        if self._out is None:
            raise Error("ri.%s before ri.Begin: a RIB stream must be begun first" % name)
        words = [name]
        for arg in args:
            if isinstance(arg, dict):
                words.extend(_parameters(arg))
            elif arg is None:
                continue
            else:
                words.append(_value(arg))
        if name.endswith("End"):
            self._indent = max(0, self._indent - 1)
        self._write(" ".join(words))
        if name.endswith("Begin"):
            self._indent += 1

    def _write(self, line):
        self._out.write("    " * self._indent + line + "\n")


def Init(arguments=None):
    """RenderMan 24's start-up call with prman's command-line options: nothing to do here."""


def Cleanup():
    """RenderMan 24's shut-down call: nothing to do here."""


def RicGetProgress():
    """How far the render has come, in percent: renders here are done when End returns."""
    return 100
