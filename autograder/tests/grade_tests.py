#!/usr/bin/env python3
"""The autograder's own tests: rixgrade on mutants, correct variants, hostile
plugins, attacking submissions and whole classes, each checked from outside.

    grade_tests.py --rixgrade BIN --root COURSE --build BUILD --out OUT [--port P] KIND [NAME]

KIND is variant, hostile, attack, solutions, starter, repeat or class. Prints
what it checked; exits 1 with lines starting PROBLEM when something is wrong.
"""
import argparse
import base64
import csv
import glob
import hashlib
import io
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

# Short limits: the tests grade many small things.
TEST_RUBRIC = {"check_timeout_s": 20, "render_spp": 4, "render_timeout_s": 120,
               "configure_timeout_s": 60, "build_timeout_s": 180}

problems = []


def problem(text):
    problems.append(text)
    print("PROBLEM:", text)


def expect(condition, text):
    if not condition:
        problem(text)
    return condition


class Context:
    def __init__(self, args):
        self.rixgrade = args.rixgrade
        self.root = args.root
        self.build = args.build
        self.out = args.out
        self.port = args.port

    def rubric(self, name, **changes):
        rubric = dict(TEST_RUBRIC, **changes)
        path = os.path.join(self.out, name + "-rubric.json")
        with open(path, "w") as f:
            json.dump(rubric, f)
        return path

    def grade(self, name, *arguments, rubric=None, env=None, timeout=900):
        """Runs rixgrade; returns (exit status, output, seconds). Reports go to OUT/name."""
        folder = os.path.join(self.out, name)
        shutil.rmtree(folder, ignore_errors=True)
        command = [self.rixgrade, *arguments, "--out", folder, "--rubric", rubric or self.rubric(name)]
        start = time.time()
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                             env=env, timeout=timeout)
        seconds = time.time() - start
        with open(folder + ".log", "w") as f:
            f.write(run.stdout)
        return run.returncode, run.stdout, seconds

    def results(self, name):
        with open(os.path.join(self.out, name, "results.json")) as f:
            return json.load(f)


def checks_of(results):
    """check name -> test entry (a single plugin was graded)."""
    return {t["name"].split(": ")[-1]: t for t in results["tests"]}


def snapshot(folder):
    """Every entry below folder: kind, size, mode, modification time and contents' hash."""
    state = {}
    for base, dirs, files in os.walk(folder):
        for entry in dirs + files:
            path = os.path.join(base, entry)
            st = os.lstat(path)
            digest = ""
            if os.path.isfile(path) and not os.path.islink(path):
                with open(path, "rb") as f:
                    digest = hashlib.sha256(f.read()).hexdigest()
            state[os.path.relpath(path, folder)] = (st.st_mode, st.st_size, st.st_mtime_ns, st.st_uid, digest)
    return state


def make_canary(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(folder, "canary.txt"), "w") as f:
        f.write("precious canary\n")
    return snapshot(folder)


def all_text(folder):
    """Everything the grader wrote, as one string."""
    text = ""
    for base, _, files in os.walk(folder):
        for leaf in files:
            with open(os.path.join(base, leaf), "rb") as f:
                text += f.read().decode("utf-8", "replace")
    return text


def no_leftover_processes(marker):
    """No process of the submission outlives the grading."""
    time.sleep(0.5)
    found = subprocess.run(["pgrep", "-af", marker], stdout=subprocess.PIPE, text=True).stdout.strip()
    found = "\n".join(line for line in found.splitlines() if "pgrep" not in line and "grade_tests.py" not in line)
    expect(not found, "processes survived the grading:\n" + found)


# --- variants ---------------------------------------------------------------

def test_variant(ctx, name):
    variants = json.load(open(os.path.join(ctx.root, "autograder/tests/variants.json")))["variants"]
    v = next(v for v in variants if v["name"] == name)
    built = os.path.join(ctx.build, "plugins/variants", name, v["plugin"] + ".so")
    if not expect(os.path.isfile(built), f"{built} was not built"):
        return
    rubric = None
    if v["kind"] == "mutant":
        # A mutant is graded on the checks its entry names (and loads, where its manifest has it), as a
        # rubric that lists them would grade it: each check decides alone, so the rest would only cost time. A correct
        # variant is graded on every check, as a student is.
        path, = glob.glob(os.path.join(ctx.root, "starter", "ch*", v["plugin"], "exercise.json"))
        manifest = json.load(open(path))
        named = set(v["fail"]) | {"loads"} | ({"renders"} if "noise" in v["fail"] else set())  # noise reads renders
        checks = {check: points for check, points in manifest["checks"] if check in named}
        rubric = ctx.rubric("variant-" + name, chapters={manifest["chapter"]: {v["plugin"]: {"checks": checks}}})
    status, output, _ = ctx.grade("variant-" + name, "--plugins", os.path.join(ctx.build, "plugins/variants", name),
                                  "--only", v["plugin"], rubric=rubric)
    if not expect(status == 0, f"rixgrade exited with {status}:\n{output[-2000:]}"):
        return
    checks = checks_of(ctx.results("variant-" + name))
    print(f"{name} ({v['kind']}: {v['bug']})")
    for check, t in checks.items():
        print(f"  {t['status']:6} {check}: {t['output'].splitlines()[0][:200]}")
    if v["kind"] == "correct":
        for check, t in checks.items():
            expect(t["status"] == "passed", f"the correct variant fails {check}: {t['output'][:400]}")
    else:
        for check in v["fail"]:
            expect(check in checks, f"{check} was not graded")
            expect(checks.get(check, {}).get("status") == "failed", f"the mutant ({v['bug']}) passes {check}")
        # A Bxdf loads: one that does not fails every check, and would otherwise look caught
        # by the checks its entry names.
        if "loads" in checks and "loads" not in v["fail"]:
            expect(checks["loads"]["status"] == "passed", f"the mutant does not load: {checks['loads']['output'][:400]}")


# --- hostile plugins ----------------------------------------------------------

def listen(port, received):
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(("127.0.0.1", port))
    server.listen(5)
    server.settimeout(0.5)
    while not received.get("stop"):
        try:
            connection, _ = server.accept()
        except socket.timeout:
            continue
        received.setdefault("data", b"")
        received["data"] += connection.recv(65536)
        connection.close()
    server.close()


def test_hostile(ctx, act):
    canary = os.path.join(ctx.out, "canary-" + act)
    before = make_canary(canary)
    secret = "s3cret-" + hashlib.sha256(os.urandom(8)).hexdigest()[:12]
    env = dict(os.environ, RIXGRADE_TEST_SECRET=secret)
    received = {}
    listener = threading.Thread(target=listen, args=(ctx.port, received))
    listener.start()
    try:
        rubric = ctx.rubric("hostile-" + act, check_timeout_s=8)
        status, output, seconds = ctx.grade("hostile-" + act, "--plugins", os.path.join(ctx.build, "plugins/hostile", act),
                                            "--only", "diffuse", rubric=rubric, env=env)
    finally:
        received["stop"] = True
        listener.join()
    print(output[-3000:])
    if not expect(status == 0, f"rixgrade exited with {status}"):
        return
    results = ctx.results("hostile-" + act)
    checks = checks_of(results)
    written = all_text(os.path.join(ctx.out, "hostile-" + act))
    expect(snapshot(canary) == before, "the canary folder outside the sandbox changed")
    expect(secret not in written, "a report contains the grader's secret environment variable")
    expect("precious canary" not in written, "a report contains a file from outside the sandbox")
    expect("root:x:0" not in written, "a report contains the machine's /etc/passwd")
    expect(not received.get("data"), f"the plugin reached the network: {received.get('data', b'')[:200]!r}")
    no_leftover_processes("plugins/hostile/" + act)
    mentions = lambda text: any(text in t["output"] for t in results["tests"])
    failed = lambda check: checks[check]["status"] == "failed"
    passed = lambda check: checks[check]["status"] == "passed"
    generating = ["chi2", "consistency", "jacobian", "hardcases", "renders"]
    if act in ("segfault", "abort", "throws", "huge_allocation", "fork_bomb"):
        for check in generating:
            expect(failed(check), f"{check} passes although GenerateSample never answers")
        expect(passed("values"), "values (EvaluateSample, which works) should pass: " + checks["values"]["output"])
        expect(mentions("GenerateSample"), "no message names GenerateSample as the function that failed")
    if act == "segfault":
        expect(mentions("SIGSEGV"), "no message says SIGSEGV")
        # A crash's hint is about memory, not the hint of the check it cut short.
        chi2 = checks["chi2"]["output"]
        expect("Hint: Memory read or written that the plugin does not own" in chi2 and "rixwarp" not in chi2,
               "the crash in chi2 is given chi2's own hint: " + chi2)
    if act == "abort":
        expect(mentions("SIGABRT"), "no message says SIGABRT")
    if act == "throws":
        expect(mentions("threw an exception in GenerateSample"), "no message says GenerateSample threw")
    if act == "fork_bomb":
        expect(mentions("tried to start a process"), "no message says it tried to start a process")
    if act == "endless_loop":
        expect(mentions("did not answer within"), "no message says the plugin did not answer")
        expect(mentions("remaining checks are skipped"), "the remaining checks were run after a hang")
        expect(seconds < 8 * 2 + 60, f"a hanging plugin cost {seconds:.0f} s: more than one timeout")
    if act == "exit_zero":
        expect(results["score"] == 0, f"a plugin that exits at once scored {results['score']}")
    if act in ("writes_outside", "steals", "phones_home", "floods_stdout", "kills_grader"):
        for check, t in checks.items():
            expect(t["status"] == "passed", f"{check} should pass (the plugin is otherwise correct): {t['output'][:300]}")
    if act == "floods_stdout":
        size = os.path.getsize(os.path.join(ctx.out, "hostile-" + act, "report.html"))
        expect(size < 300000, f"the report grew to {size} bytes: a plugin's output is not capped")
    if act == "fake_image":
        expect(failed("renders"), "a fake image passed the render check")
        expect("image" in checks["renders"]["output"], "the render check does not say the image was not valid")


# --- whole submissions ---------------------------------------------------------

MINIMAL_CMAKE = """cmake_minimum_required(VERSION 3.22)
project(Submission LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 17)
include(${BXDFLAB_ROOT}/cmake/RixPlugin.cmake)
set(RIX_PLUGIN_OUTPUT_DIR ${CMAKE_BINARY_DIR}/plugins)
add_rix_plugin(diffuse ch06/diffuse/DiffuseFactory.cpp ch06/diffuse/Diffuse.cpp)
target_include_directories(diffuse PRIVATE ch06/diffuse common)
"""


def make_submission(ctx, folder, solved=True, cmake_extra="", whole=False):
    """A submission folder: the starter's diffuse (solved or not), or the whole starter."""
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(os.path.join(ctx.root, "starter"), folder, symlinks=True)
    if solved:
        for leaf in ("Diffuse.cpp", "Diffuse.h", "DiffuseFactory.cpp", "DiffuseFactory.h"):
            shutil.copy(os.path.join(ctx.root, "solutions/ch06/diffuse", leaf), os.path.join(folder, "ch06/diffuse", leaf))
    if not whole:
        with open(os.path.join(folder, "CMakeLists.txt"), "w") as f:
            f.write(MINIMAL_CMAKE + cmake_extra)
    return folder


def diffuse_points(results):
    return sum(t["score"] for t in results["tests"]), sum(t["max_score"] for t in results["tests"])


def test_attack(ctx, name):
    work = os.path.join(ctx.out, "attack-" + name + "-work")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    canary = os.path.join(work, "canary")
    before = make_canary(canary)
    course_file = os.path.join(ctx.root, "scenes/ch06/diffuse.rib")
    course_before = snapshot(os.path.dirname(course_file))
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    env = dict(os.environ, TMPDIR=tmp)
    report = os.path.join(ctx.out, "attack-" + name)
    if name == "odd_names" or name == "classmate_source":
        return test_class_attack(ctx, name, work, env)

    extra = ""
    rubric = None
    if name == "daemon":
        # A detached process that outlives the build and rewrites the results later.
        # (4.0071 s: a duration no other process on the machine is likely to sleep, for the leftover check)
        extra = ('execute_process(COMMAND sh -c "setsid sh -c \'sleep 4.0071; echo HACKED > ' + report +
                 '/results.json; echo HACKED > /scratch/pwned\' > /dev/null 2>&1 &")\n')
    elif name == "writes_outside_build":
        # Every write a shell can try, each allowed to fail quietly so the rest of the build goes on.
        script = (f"echo defaced > {canary}/canary.txt; touch {canary}/planted; chmod 777 {canary}/canary.txt; "
                  f"touch -d 2000-01-01 {canary}/canary.txt; ln -s /etc/passwd {report}/report.html; "
                  f"ln -s {canary}/canary.txt {report}/results.json; : > {course_file}; "
                  f"echo x > /scratch/../escaped; echo x > {work}/escaped; true")
        extra = f'execute_process(COMMAND sh -c "{script}")\n'
    elif name == "huge_file":
        extra = ('execute_process(COMMAND dd if=/dev/zero of=big bs=1M count=2048 RESULT_VARIABLE r ERROR_VARIABLE e)\n'
                 'message(STATUS "dd: ${r}")\n')
    elif name == "sleeping_configure":
        extra = 'execute_process(COMMAND sleep 1000)\n'
        rubric = ctx.rubric("attack-" + name, configure_timeout_s=5)
    elif name == "kills_grader_build":
        extra = 'execute_process(COMMAND sh -c "kill -9 $PPID; kill -9 -1")\n'
    elif name == "course_plugin":
        # The untouched starter's sources, and the course's compiled PxrDiffuse (the diffuse solution under
        # another name) copied over what they build, from wherever the course might be seen.
        extra = ('add_custom_command(TARGET diffuse POST_BUILD COMMAND sh -c "cp /course/plugins/stock/PxrDiffuse.so '
                 '$<TARGET_FILE:diffuse> || cp ' + ctx.build + '/plugins/stock/PxrDiffuse.so $<TARGET_FILE:diffuse> '
                 '|| true")\n')
    elif name == "prebuilt_plugin":
        # The untouched starter's sources, and a finished plugin (a classmate's, say) copied over what they build.
        extra = ("add_custom_command(TARGET diffuse POST_BUILD COMMAND ${CMAKE_COMMAND} -E copy "
                 "${CMAKE_SOURCE_DIR}/prebuilt/diffuse.so $<TARGET_FILE:diffuse>)\n")
    submission = make_submission(ctx, os.path.join(work, "submission"), solved=(name not in ("prebuilt_plugin", "course_plugin")),
                                 cmake_extra=extra, whole=(name == "broken_plugin"))
    if name == "prebuilt_plugin":
        os.makedirs(os.path.join(submission, "prebuilt"))
        shutil.copy(os.path.join(ctx.build, "plugins/solutions/diffuse.so"), os.path.join(submission, "prebuilt"))
    if name == "broken_plugin":
        # Every exercise solved, but the specular plugin does not compile.
        for chapter, plugin in (("ch06", "emissive"), ("ch06", "specular"), ("ch06", "plastic")):
            for leaf in os.listdir(os.path.join(ctx.root, "solutions", chapter, plugin)):
                shutil.copy(os.path.join(ctx.root, "solutions", chapter, plugin, leaf),
                            os.path.join(submission, chapter, plugin, leaf))
        with open(os.path.join(submission, "ch06/specular/Specular.cpp"), "a") as f:
            f.write("\nthis is not C++;\n")
    arguments = ["--submission", submission]
    arguments += ["--chapter", "6"] if name == "broken_plugin" else ["--only", "diffuse"]
    status, output, seconds = ctx.grade("attack-" + name, *arguments, rubric=rubric, env=env)
    print(output[-3000:])
    if not expect(status == 0, f"rixgrade exited with {status}"):
        return
    results = ctx.results("attack-" + name)
    checks = {t["name"]: t for t in results["tests"]}
    expect(snapshot(canary) == before, "the canary folder outside the sandbox changed")
    expect(snapshot(os.path.dirname(course_file)) == course_before, "a file of the course changed")
    expect(not os.path.exists(os.path.join(work, "escaped")), "the build wrote outside its scratch folder")
    for leaf in ("report.html", "results.json"):
        path = os.path.join(report, leaf)
        expect(os.path.isfile(path) and not os.path.islink(path), f"{leaf} is not a regular file the grader wrote")
    expect(os.listdir(tmp) == [], f"the scratch folder was left behind: {os.listdir(tmp)}")
    no_leftover_processes("sleep 4\\.0071")
    if name in ("daemon", "writes_outside_build", "huge_file"):
        score, maximum = diffuse_points(results)
        expect(score == maximum, f"an otherwise correct diffuse scored {score} of {maximum}")
    if name == "daemon":
        before_hash = hashlib.sha256(open(os.path.join(report, "results.json"), "rb").read()).hexdigest()
        time.sleep(6)
        after_hash = hashlib.sha256(open(os.path.join(report, "results.json"), "rb").read()).hexdigest()
        expect(before_hash == after_hash, "results.json changed after rixgrade returned")
    if name == "huge_file":
        log = open(os.path.join(report, "report.html")).read()
        expect("dd: SIGXFSZ" in log or "dd: File size limit exceeded" in log, "the build log does not show the 2 GiB write stopped by the file size limit")
    if name == "sleeping_configure":
        expect(seconds < 90, f"a sleeping configure step held grading for {seconds:.0f} s")
        expect("did not finish within 5 s" in json.dumps(results) + open(report + "/report.html").read(),
               "the report does not say the configure step timed out")
    if name == "prebuilt_plugin":
        score, maximum = diffuse_points(results)
        expect(score < maximum, f"the starter's diffuse with a finished plugin brought along scored {score} of {maximum}")
        expect("compiled code" in open(os.path.join(report, "report.html")).read(),
               "the report does not say the brought-along library was left out")
    if name == "course_plugin":
        # Only the starter's own code is graded: it earns what the untouched starter earns (loads, at most).
        expect(checks_of(results).get("values", {}).get("status") == "failed", "the copied course plugin passed values")
        score, maximum = diffuse_points(results)
        expect(score <= 1, f"the starter's diffuse with the course's PxrDiffuse copied over it scored {score} of {maximum}")
    if name == "broken_plugin":
        diffuse = [t for n, t in checks.items() if " diffuse:" in n]
        specular = [t for n, t in checks.items() if " specular:" in n]
        expect(all(t["status"] == "passed" for t in diffuse), "a broken specular cost diffuse its points")
        expect(all(t["score"] == 0 for t in specular), "a specular that does not compile earned points")
        expect(any("Specular.cpp" in t["output"] for t in specular), "the compiler's error is not quoted for specular")


def test_class_attack(ctx, name, work, env):
    klass = os.path.join(work, "class")
    os.makedirs(klass)
    if name == "classmate_source":
        make_submission(ctx, os.path.join(klass, "alice"))
        alice_source = os.path.join(klass, "alice/ch06/diffuse/Diffuse.cpp")
        # mallory compiles alice's file by its absolute path; trudy links to it.
        make_submission(ctx, os.path.join(klass, "mallory"), solved=False,
                        cmake_extra=f"target_sources(diffuse PRIVATE {alice_source})\n"
                                    "set_source_files_properties(ch06/diffuse/Diffuse.cpp PROPERTIES HEADER_FILE_ONLY ON)\n")
        trudy = make_submission(ctx, os.path.join(klass, "trudy"), solved=False)
        os.remove(os.path.join(trudy, "ch06/diffuse/Diffuse.cpp"))
        os.symlink(alice_source, os.path.join(trudy, "ch06/diffuse/Diffuse.cpp"))
        os.symlink("../../../alice/ch06/diffuse/Diffuse.h", os.path.join(trudy, "ch06/diffuse/Extra.h"))
        # carol copies alice's code and renames things: the similarity report must flag it.
        carol = make_submission(ctx, os.path.join(klass, "carol"), solved=False)
        text = open(alice_source).read().replace("NdL", "cosLight").replace("weight", "w")
        with open(os.path.join(carol, "ch06/diffuse/Diffuse.cpp"), "w") as f:
            f.write(text)
        # eve brings a finished plugin and copies it over what her untouched starter builds.
        eve = make_submission(ctx, os.path.join(klass, "eve"), solved=False,
                              cmake_extra="add_custom_command(TARGET diffuse POST_BUILD COMMAND ${CMAKE_COMMAND} -E copy "
                                          "${CMAKE_SOURCE_DIR}/lib/libdiffuse.so $<TARGET_FILE:diffuse>)\n")
        os.makedirs(os.path.join(eve, "lib"))
        shutil.copy(os.path.join(ctx.build, "plugins/solutions/diffuse.so"), os.path.join(eve, "lib/libdiffuse.so"))
        # frank carries the same plugin as base64 text in a header (to write out and load at run time).
        frank = make_submission(ctx, os.path.join(klass, "frank"), solved=False)
        encoded = base64.encodebytes(open(os.path.join(ctx.build, "plugins/solutions/diffuse.so"), "rb").read()).decode()
        with open(os.path.join(frank, "ch06/diffuse/Payload.h"), "w") as f:
            f.write("static const char* kPayload =\n" + "".join(f'"{line}"\n' for line in encoded.split()) + ";\n")
    else:
        names = ["gradebook.csv", "a,b", 'quote"name', '=HYPERLINK("http://x")', "new\nline", "+1", "@sum", "ok"]
        for n in names:
            make_submission(ctx, os.path.join(klass, n), solved=(n == "ok"))
        with open(os.path.join(klass, "not-a-folder.txt"), "w") as f:
            f.write("stray file")
    status, output, _ = ctx.grade("attack-" + name, "--class", klass, "--jobs", "2", "--only", "diffuse", env=env)
    print(output[-3000:])
    if not expect(status == 0, f"rixgrade exited with {status}"):
        return
    out = os.path.join(ctx.out, "attack-" + name)
    raw = open(os.path.join(out, "gradebook.csv"), newline="").read()
    rows = list(csv.reader(io.StringIO(raw)))
    header, body = rows[0], rows[1:]
    expect(all(len(r) == len(header) for r in body), "gradebook rows do not all have the header's number of fields")
    by_name = {r[0]: r for r in body}
    students = sorted(os.listdir(klass))
    submissions = [s for s in students if os.path.isdir(os.path.join(klass, s))]
    expect(len(body) == len(submissions), f"the gradebook has {len(body)} rows for {len(submissions)} students")
    score = lambda n: float(by_name[n][1]) if n in by_name else -1
    if name == "classmate_source":
        expect(score("alice") == float(by_name["alice"][2]), "alice did not get full marks")
        for thief in ("mallory", "trudy"):
            expect(score(thief) <= 1, f"{thief} earned {score(thief)} by compiling a classmate's file")
        similar = list(csv.reader(open(os.path.join(out, "similarity.csv"), newline="")))
        flagged = [r for r in similar[1:] if {r[0], r[1]} == {"alice", "carol"} and int(r[4]) >= 60]
        expect(flagged, "the similarity report does not flag carol's copy of alice's code")
        expect("carol" in open(os.path.join(out, "report.html")).read(), "the class report does not show the copy")
        expect(score("eve") <= 1, f"eve earned {score('eve')} with a plugin built elsewhere")
        report_text = open(os.path.join(out, "report.html")).read()
        expect("look at: lib/libdiffuse.so (compiled code" in report_text,
               "the class report does not say eve brought compiled code")
        expect("look at: ch06/diffuse/Payload.h (" in report_text and "characters of base64 or hex text" in report_text,
               "the class report does not point at frank's plugin carried as base64 text")
        expect(report_text.count("look at:") == 2, "the class report points at files of honest submissions")
    else:
        for n in ("gradebook.csv", "a,b", 'quote"name', "'+1", "'@sum", "ok"):
            expect(n in by_name, f"no gradebook row for {n!r}")
        formula = [r[0] for r in body if r[0][:1] in ("=", "+", "-", "@")]
        expect(not formula, f"cells a spreadsheet would run as formulas: {formula}")
        expect("'=HYPERLINK" in raw, "the formula-like name is not neutralised")
        expect(score("ok") == float(by_name["ok"][2]), "the honest student 'ok' did not get full marks")
        expect(os.path.isfile(os.path.join(out, "gradebook.csv")), "no gradebook")


def test_solutions(ctx):
    status, output, seconds = ctx.grade("solutions", "--plugins", os.path.join(ctx.build, "plugins/solutions"))
    print(output[-4000:])
    if expect(status == 0, f"rixgrade exited with {status}"):
        results = ctx.results("solutions")
        for t in results["tests"]:
            expect(t["status"] == "passed", f"the reference solution fails {t['name']}: {t['output'][:300]}")
        print(f"solutions: {results['score']} / {results['max_score']} in {seconds:.1f} s")


def confinements(ctx):
    """The sandbox, and --unsafe-no-sandbox where rixgrade can use it here (it says when it cannot)."""
    if os.geteuid() == 0 and not (nobody_can_enter(ctx.root) and nobody_can_enter(ctx.build)):
        print("skipped without the sandbox: the course lies below a folder closed to other users, where rixgrade "
              "refuses --unsafe-no-sandbox (autograder.unsafe checks that refusal)")
        return [[]]
    return [[], ["--unsafe-no-sandbox"]]


def grade_borrowing(ctx, name, plugin):
    """Grades the hostile plugin folder `name` (a plugin that loads the course's own) for `plugin`, in
    the sandbox and without it; yields (where, checks) for each grading that finished."""
    plugins = os.path.join(ctx.build, "plugins/hostile", name)
    for confinement in confinements(ctx):
        report = name.replace("_", "-") + ("-unsafe" if confinement else "")
        status, output, _ = ctx.grade(report, "--plugins", plugins, "--only", plugin, *confinement)
        print(output[-2000:])
        if expect(status == 0, f"rixgrade exited with {status}"):
            yield " ".join(confinement) or "in the sandbox", checks_of(ctx.results(report))


def test_borrows_reference(ctx):
    """A ch11 submission whose mypath loads the course's PxrPathTracer earns nothing for it, in the
    sandbox (not mounted) and without it (Landlock keeps reads to what a sandbox would see)."""
    for where, checks in grade_borrowing(ctx, "borrows_reference", "mypath"):
        expect("renders" in checks, "renders was not graded")
        for check in ("renders", "noise"):
            if check in checks:
                expect(checks[check]["status"] == "failed", f"{where}: the borrowed reference integrator passes {check}")
        # Its CreateRixIntegrator finds nothing to load and returns null: the failure is isolation,
        # not a small difference between the reference and the exercise's solution.
        renders = checks.get("renders", {}).get("output", "")
        expect("refused its parameters" in renders, f"{where}: the reference integrator was within reach: {renders[:300]}")


def test_borrows_stock(ctx):
    """A ch06 submission whose diffuse hands over the stock PxrDiffuse (the diffuse solution under
    another name) earns nothing: no stage of its grading has that plugin within reach, in the
    sandbox or without it."""
    for where, checks in grade_borrowing(ctx, "borrows_stock", "diffuse"):
        score = sum(t["score"] for t in checks.values())
        expect(score == 0, f"{where}: the stock diffuse handed over earned {score} points")
        # Its factory finds nothing to load and returns null, in the checks and in the render.
        for check in ("loads", "values", "renders"):
            expect("CreateRixBxdfFactory returned null" in checks.get(check, {}).get("output", ""),
                   f"{where}: the stock diffuse was within reach of the {check} check")


API_SAMPLING = """#include "Sampling.h"
#include "RixShadingUtils.h"
namespace sampling {
RtVector3 sampleUniformHemisphere(RtFloat2 const& xi, float* pdf) {
    RtVector3 out; float c;
    RixUniformDirectionalDistribution(xi, RtNormal3(0, 0, 1), RtVector3(1, 0, 0), RtVector3(0, 1, 0), out, c);
    *pdf = F_INVTWOPI;
    return out;
}
float uniformHemispherePdf(RtVector3 const& w) { return w.z > 0 ? F_INVTWOPI : 0.0f; }
RtVector3 sampleCosineHemisphere(RtFloat2 const& xi, float* pdf) {
    RtVector3 out; float c;
    RixCosDirectionalDistribution(xi, RtNormal3(0, 0, 1), RtVector3(1, 0, 0), RtVector3(0, 1, 0), out, c);
    *pdf = c * F_INVPI;
    return out;
}
float cosineHemispherePdf(RtVector3 const& w) { return w.z > 0 ? w.z * F_INVPI : 0.0f; }
RtVector3 samplePhongLobe(RtFloat2 const& xi, float n, float* pdf) {
    RtVector3 out; float c;
    RixPhongLobeDirectionalDistribution(xi, n, RtVector3(0, 0, 1), out, c);
    *pdf = RixPhongLobePdf(c, n);
    return out;
}
float phongLobePdf(RtVector3 const& w, float n) { return RixPhongLobePdf(w.z, n); }
}  // namespace sampling
"""


def test_writes_it_yourself(ctx):
    """The chapter-8 sampling exercise asks for samplers the API already has: the grader compiles it
    from its own sources with those functions poisoned, so a submission that calls the API's
    (directly, through a header of its own, or with the name pasted together by a macro) earns
    nothing and is told where; the reference solution's own code, submitted as sources, earns
    everything."""
    work = os.path.join(ctx.out, "writes-it-yourself-work")
    shutil.rmtree(work, ignore_errors=True)
    own = os.path.join(ctx.root, "solutions/ch08/sampling")
    # The solution's own samplers with its Phong pdf handed to the API, through a header of the
    # submission or through a macro that pastes the name together.
    with open(os.path.join(own, "Sampling.cpp")) as f:
        solution = f.read()
    phong = "return (n + 1.0f) * F_INVTWOPI * std::pow(w.z, n);"
    expect(phong in solution, "the solution's Phong pdf is no longer where the test expects it")
    hidden_in_header = solution.replace('#include "Sampling.h"\n', '#include "Sampling.h"\n#include "Helpers.h"\n').replace(
        phong, "return helper(w.z, n);")
    pasted = solution.replace('#include "Sampling.h"\n',
                              '#include "Sampling.h"\n#include "RixShadingUtils.h"\n#define PASTE(a, b) a##b\n').replace(
        phong, "return PASTE(RixPhongLobe, Pdf)(w.z, n);")
    helper = ('#pragma once\n#include "RixShadingUtils.h"\n'
              'inline float helper(float c, float n) { return RixPhongLobePdf(c, n); }\n')
    cases = {"calls": (API_SAMPLING, {}, ["Sampling.cpp:", 'attempt to use poisoned "RixUniformDirectionalDistribution"']),
             "header": (hidden_in_header, {"common/Helpers.h": helper},
                        ["common/Helpers.h:", 'attempt to use poisoned "RixPhongLobePdf"']),
             "pasted": (pasted, {}, ["Sampling.cpp:", 'attempt to use poisoned "RixPhongLobePdf"']),
             "own": (None, {}, None)}
    # Without the sandbox too (rixgrade maps its folders back to the real ones there).
    if len(confinements(ctx)) > 1:
        cases["calls-unsafe"] = cases["calls"]
    for case, (source, extra, said) in cases.items():
        folder = os.path.join(work, case)
        shutil.copytree(os.path.join(ctx.root, "starter"), folder, symlinks=True)
        for leaf in os.listdir(own):
            shutil.copy(os.path.join(own, leaf), os.path.join(folder, "ch08/sampling", leaf))
        if source is not None:
            with open(os.path.join(folder, "ch08/sampling/Sampling.cpp"), "w") as f:
                f.write(source)
        for relative, text in extra.items():
            with open(os.path.join(folder, relative), "w") as f:
                f.write(text)
        name = "writes-it-yourself-" + case
        unsafe = ["--unsafe-no-sandbox"] if case.endswith("-unsafe") else []
        status, output, _ = ctx.grade(name, "--submission", folder, "--only", "sampling", *unsafe)
        print(output[-1500:])
        if not expect(status == 0, f"{case}: rixgrade exited with {status}"):
            continue
        results = ctx.results(name)
        score = sum(t["score"] for t in results["tests"])
        maximum = sum(t["max_score"] for t in results["tests"])
        if said is None:
            expect(score == maximum, f"the solution's own samplers, as sources, scored {score} of {maximum}")
        else:
            expect(score == 0, f"{case}: samplers handed to the API scored {score} of {maximum}")
            for words in said:
                expect(all(words in t["output"] for t in results["tests"]), f"{case}: the report does not say '{words}'")


def test_borrows_other_stock(ctx):
    """A ch09 ggx that hands over the stock PxrDisney (a GGX lobe of its own, which the chapter-11
    scenes load) finds it in no stage: a render mounts only the stock plugins its scene loads."""
    for where, checks in grade_borrowing(ctx, "borrows_other_stock", "ggx"):
        expect("renders" in checks, "renders was not graded")
        for check in ("loads", "renders"):
            expect("CreateRixBxdfFactory returned null" in checks.get(check, {}).get("output", ""),
                   f"{where}: PxrDisney was within reach of the {check} check")


def test_render_cache(ctx):
    """Reference renders kept between runs: the same grade from the cache, a damaged entry rendered again,
    a rebuilt solution never served from an entry made with the old one, one entry per scene, spp and seed."""
    cache = os.path.join(ctx.build, "grader-cache")
    scene = os.path.join(ctx.root, "scenes", "ch06", "diffuse.rib")

    def entries():
        """subject ("scene ...; spp ...; seed ...;") -> [(file, key)] for the scene."""
        found = {}
        for leaf in sorted(os.listdir(cache)) if os.path.isdir(cache) else []:
            with open(os.path.join(cache, leaf), "rb") as f:
                key = f.readline().decode("utf-8", "replace").rstrip("\n")
            if key.startswith("scene " + scene + ";"):
                subject = ";".join(key.split(";")[:3]) + ";"
                found.setdefault(subject, []).append((leaf, key))
        return found

    def grade(name):
        status, output, _ = ctx.grade(name, "--plugins", os.path.join(ctx.build, "plugins/solutions"), "--only", "diffuse")
        expect(status == 0, f"rixgrade exited with {status}:\n{output[-1500:]}")
        return {check: (t["status"], t["output"]) for check, t in checks_of(ctx.results(name)).items()}

    for subject, found in entries().items():  # start from nothing for this scene (a cache may always be emptied)
        for leaf, _ in found:
            os.remove(os.path.join(cache, leaf))
    first = grade("cache-first")
    made = entries()
    expect(made and all(len(v) == 1 for v in made.values()), f"not one cache entry per scene and spp: {made}")
    expect(first == grade("cache-again"), "grading from the cached reference render changed the grade")

    for subject, [(leaf, key)] in made.items():  # damage every image, keep the keys
        with open(os.path.join(cache, leaf), "r+b") as f:
            f.seek(len(key) + 1 + 40)
            f.truncate()
    expect(first == grade("cache-damaged"), "a damaged cache entry changed the grade")

    os.utime(os.path.join(ctx.build, "plugins/solutions/diffuse.so"))  # as a rebuild would
    grade("cache-rebuilt")
    after = entries()
    for subject, [(leaf, key)] in made.items():
        now = after.get(subject, [])
        expect(len(now) == 1 and now[0][1] != key, f"{subject}: the entry made with the old solution was not replaced")


def test_starter(ctx):
    status, output, _ = ctx.grade("starter", "--plugins", os.path.join(ctx.build, "plugins/starter"), "--chapter", "6",
                                  "10", "11")
    print(output[-4000:])
    if expect(status == 0, f"rixgrade exited with {status}"):
        results = ctx.results("starter")
        checks = {t["name"]: t for t in results["tests"]}
        expect(checks["ch6 diffuse: loads"]["status"] == "passed", "the untouched starter does not load")
        expect(checks["ch6 diffuse: values"]["status"] == "failed", "the untouched starter passes values")
        expect(any("TODO bodies" in t["output"] for t in results["tests"]), "no message points at the TODO bodies")
        # An untouched integrator renders black: it must not earn the noise points for being smooth.
        for name, t in checks.items():
            if name.startswith("ch11 "):
                expect(t["status"] == "failed", f"the untouched starter passes {name}")
        # Chapter 10's starter gives the plumbing but no physics: only "loads" may pass.
        expect(any(name.startswith("ch10 ") for name in checks), "chapter 10 was not graded")
        for name, t in checks.items():
            if name.startswith("ch10 ") and name != "ch10 glass: loads":
                expect(t["status"] == "failed", f"the untouched starter passes {name}")


def test_rixcheck_crash(ctx):
    """A plugin runs inside rixcheck: when it crashes, rixcheck says which check and plugin call, then exits 1."""
    rixcheck = os.path.join(os.path.dirname(ctx.rixgrade), "rixcheck")
    # The last overwrites its own return address: the report must not need the stack it wrecked.
    for folder, call in (("hostile/segfault", "GenerateSample"),
                         ("variants/diffuse_shading_normal_never_fetched", "EvaluateSample"),
                         ("variants/diffuse_sample_array_too_small", "GenerateSample")):
        run = subprocess.run([rixcheck, "--plugin", "diffuse", "--plugin-dir", os.path.join(ctx.build, "plugins", folder)],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                             timeout=300)
        print(run.stdout[-2000:])
        expect(run.returncode == 1, f"rixcheck on {folder} exited with {run.returncode}, not 1")
        expect("\ufffd" not in run.stdout, f"{folder}: the report holds bytes that are no text")
        expect("PASS diffuse loads" in run.stdout, f"{folder}: the verdicts before the crash are lost")
        crashed = [line for line in run.stdout.splitlines() if "the plugin crashed (SIGSEGV) in " + call in line]
        expect(len(crashed) == 1 and crashed[0].startswith("FAIL diffuse "),
               f"{folder}: no FAIL line names the crash in {call}")
        expect("hint: Memory read or written that the plugin does not own" in run.stdout, f"{folder}: no hint")


def nobody_can_enter(path):
    """Whether the user nobody may pass through every folder down to path (others' x bit)."""
    folder = os.path.realpath(path)
    while True:
        st = os.stat(folder)
        if st.st_uid != 65534 and not st.st_mode & 0o001:
            return False
        if folder == "/":
            return True
        folder = os.path.dirname(folder)


def test_unsafe(ctx):
    """Where namespaces are missing an instructor may grade without the sandbox; every report says so."""
    if os.geteuid() == 0 and not (nobody_can_enter(ctx.root) and nobody_can_enter(ctx.build)):
        # Student code would run as nobody straight from these folders: rixgrade must refuse, by name.
        status, output, _ = ctx.grade("unsafe", "--plugins", os.path.join(ctx.build, "plugins/solutions"), "--only",
                                      "diffuse", "--unsafe-no-sandbox")
        expect(status == 1 and "nobody" in output, f"a course nobody cannot enter is not refused ({status}):\n{output}")
        print("the course lies below a folder closed to other users: checked that grading without the sandbox is "
              "refused; the graded runs without the sandbox are skipped here")
        return
    status, output, _ = ctx.grade("unsafe", "--plugins", os.path.join(ctx.build, "plugins/solutions"), "--only", "diffuse",
                                  "--unsafe-no-sandbox")
    if expect(status == 0, f"rixgrade exited with {status}:\n{output[-2000:]}"):
        results = ctx.results("unsafe")
        expect(all(t["status"] == "passed" for t in results["tests"]), "the solution fails without the sandbox")
        expect("--unsafe-no-sandbox" in results["output"], "results.json does not say the sandbox was off")
        expect("--unsafe-no-sandbox" in open(os.path.join(ctx.out, "unsafe", "report.html")).read(),
               "the report does not say the sandbox was off")
    # Without the sandbox the render must still use the student's plugin: the planted bugs
    # of the untouched buggydiffuse starter fail the render check there as they do inside it.
    status, output, _ = ctx.grade("unsafe-buggy", "--plugins", os.path.join(ctx.build, "plugins/starter"), "--only",
                                  "buggydiffuse", "--unsafe-no-sandbox")
    if expect(status == 0, f"rixgrade exited with {status}:\n{output[-2000:]}"):
        checks = checks_of(ctx.results("unsafe-buggy"))
        expect(checks.get("renders", {}).get("status") == "failed",
               "without the sandbox the buggy starter passes the render check (the solution was rendered instead)")


def test_targeted_build(ctx):
    """Grading some exercises builds only their plugins; a submission whose CMakeLists names a
    plugin's target otherwise is built whole, and graded as it was."""
    work = os.path.join(ctx.out, "targeted-build-work")
    shutil.rmtree(work, ignore_errors=True)
    cases = {"whole": make_submission(ctx, os.path.join(work, "whole"), whole=True),
             "renamed": make_submission(ctx, os.path.join(work, "renamed"))}
    renamed_cmake = MINIMAL_CMAKE.replace("Diffuse.cpp)", "Diffuse.cpp TARGET lambert)").replace(
        "target_include_directories(diffuse", "target_include_directories(lambert")
    expect(renamed_cmake != MINIMAL_CMAKE, "the minimal CMakeLists no longer has the lines the test renames")
    with open(os.path.join(cases["renamed"], "CMakeLists.txt"), "w") as f:
        f.write(renamed_cmake)
    for case, folder in cases.items():
        name = "targeted-build-" + case
        status, output, _ = ctx.grade(name, "--submission", folder, "--only", "diffuse")
        if not expect(status == 0, f"{case}: rixgrade exited with {status}:\n{output[-1500:]}"):
            continue
        for check, t in checks_of(ctx.results(name)).items():
            expect(t["status"] == "passed", f"{case}: the solved diffuse fails {check}: {t['output'][:300]}")
        with open(os.path.join(ctx.out, name, "report.html")) as f:
            report = f.read()
        if case == "whole":
            expect("diffuse.dir" in report, "the build log does not show diffuse being built")
            expect("specular.dir" not in report, "grading diffuse alone built the specular exercise too")


def test_private_folders(ctx):
    """A TMPDIR closed to other users (mode 0700, like /root or a mktemp folder) must not stop grading.

    As root the sandboxes run as nobody, who cannot enter such a folder: the sandbox must still
    bind its scratch folder there, and grading without the sandbox must refuse up front, naming
    the folder, instead of failing every check of correct work."""
    private = tempfile.mkdtemp(prefix="private-tmp-", dir=ctx.out)
    os.chmod(private, 0o700)
    env = dict(os.environ, TMPDIR=private)
    solutions = os.path.join(ctx.build, "plugins/solutions")
    status, output, _ = ctx.grade("private-tmp", "--plugins", solutions, "--only", "diffuse", env=env)
    if expect(status == 0, f"rixgrade exited with {status}:\n{output[-2000:]}"):
        failed = [t["name"] for t in ctx.results("private-tmp")["tests"] if t["status"] != "passed"]
        expect(not failed, f"the solution fails with a private TMPDIR: {failed}")
    status, output, _ = ctx.grade("private-tmp-unsafe", "--plugins", solutions, "--only", "diffuse",
                                  "--unsafe-no-sandbox", env=env)
    if os.geteuid() == 0:
        expect(status == 1 and private in output and "nobody" in output,
               f"without the sandbox, a TMPDIR nobody cannot enter is not refused by name ({status}):\n{output[-2000:]}")
    else:
        print("not root: the sandboxes run as this user, who owns the private folder (nobody is not involved)")
        expect(status == 0, f"rixgrade --unsafe-no-sandbox exited with {status}:\n{output[-2000:]}")
    if os.geteuid() == 0 and shutil.which("setpriv"):
        # Root without CAP_SYS_ADMIN (a container) cannot remount: grading binds the real folders
        # where nobody can reach them, and says which folder stops it where nobody cannot.
        no_admin = ["setpriv", "--inh-caps=-sys_admin", "--bounding-set=-sys_admin", ctx.rixgrade]
        for label, environment in (("open", None), ("private", env)):
            folder = os.path.join(ctx.out, "private-tmp-noadmin-" + label)
            shutil.rmtree(folder, ignore_errors=True)
            run = subprocess.run(no_admin + ["--plugins", solutions, "--only", "diffuse", "--out", folder,
                                             "--rubric", ctx.rubric("private-tmp-noadmin")],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=environment, timeout=900)
            if label == "open" and nobody_can_enter(ctx.root) and nobody_can_enter(ctx.build):
                expect(run.returncode == 0 and "total 14 / 14" in run.stdout,
                       f"without CAP_SYS_ADMIN the solution is not graded in full ({run.returncode}):\n{run.stdout[-2000:]}")
            elif label == "open":  # the course itself lies below a closed folder
                expect(run.returncode == 1 and "nobody" in run.stdout,
                       f"without CAP_SYS_ADMIN a course nobody can reach is not refused ({run.returncode}):\n{run.stdout[-2000:]}")
            else:
                expect(run.returncode == 1 and private in run.stdout and "nobody" in run.stdout,
                       f"without CAP_SYS_ADMIN a private TMPDIR is not refused by name ({run.returncode}):\n{run.stdout[-2000:]}")
    shutil.rmtree(private, ignore_errors=True)


def test_repeat(ctx):
    plugins = os.path.join(ctx.build, "plugins/variants/diffuse_pdf_doubled")
    runs = []
    for run in ("a", "b"):
        status, _, _ = ctx.grade("repeat-" + run, "--plugins", plugins, "--only", "diffuse")
        expect(status == 0, "rixgrade failed")
        results = ctx.results("repeat-" + run)
        runs.append([(t["name"], t["status"], t["score"], t["output"]) for t in results["tests"]])
    expect(runs[0] == runs[1], "two gradings of the same submission differ")
    print("the same submission graded twice: identical results, numbers included")


def test_gradescope(ctx):
    """The Gradescope bundle on a simulated /autograder: setup.sh builds the course, run_autograder grades."""
    root = os.path.join(ctx.out, "gradescope")
    shutil.rmtree(root, ignore_errors=True)
    for folder in ("source", "submission", "results"):
        os.makedirs(os.path.join(root, folder))
    bundle = os.path.join(ctx.out, "autograder.zip")
    run = subprocess.run([os.path.join(ctx.root, "scripts/gradescope-bundle.sh"), bundle], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    if not expect(run.returncode == 0, "the bundle was not built:\n" + run.stdout):
        return
    subprocess.run(["python3", "-m", "zipfile", "-e", bundle, os.path.join(root, "source")], check=True)
    for leaf in ("setup.sh", "run_autograder"):
        os.chmod(os.path.join(root, "source", leaf), 0o755)
    env = dict(os.environ, AUTOGRADER_ROOT=root)
    setup = subprocess.run([os.path.join(root, "source/setup.sh")], env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    if not expect(setup.returncode == 0, "setup.sh failed:\n" + setup.stdout[-3000:]):
        return
    submission = make_submission(ctx, os.path.join(root, "submission-work"), whole=True)
    for item in os.listdir(submission):
        shutil.move(os.path.join(submission, item), os.path.join(root, "submission", item))
    graded = subprocess.run([os.path.join(root, "source/run_autograder")], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    expect(graded.returncode == 0, "run_autograder failed:\n" + graded.stdout[-3000:])
    results = json.load(open(os.path.join(root, "results/results.json")))
    checks = {t["name"]: t for t in results["tests"]}
    expect(all(t["status"] == "passed" for n, t in checks.items() if " diffuse:" in n), "diffuse was not graded as solved")
    expect(any(t["status"] == "failed" for n, t in checks.items() if " specular:" in n),
           "the untouched specular exercise was graded as solved")
    expect(set(results) >= {"score", "tests", "execution_time"}, "results.json lacks Gradescope's fields")
    print(f"Gradescope layout: {results['score']} / {results.get('max_score')}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rixgrade", required=True)
    parser.add_argument("--root", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--port", type=int, default=47613)
    parser.add_argument("kind")
    parser.add_argument("name", nargs="?")
    args = parser.parse_args()
    ctx = Context(args)
    os.makedirs(ctx.out, exist_ok=True)
    tests = {"variant": lambda: test_variant(ctx, args.name), "hostile": lambda: test_hostile(ctx, args.name),
             "borrows_reference": lambda: test_borrows_reference(ctx),
             "borrows_stock": lambda: test_borrows_stock(ctx),
             "borrows_other_stock": lambda: test_borrows_other_stock(ctx),
             "writes_it_yourself": lambda: test_writes_it_yourself(ctx), "render_cache": lambda: test_render_cache(ctx),
             "attack": lambda: test_attack(ctx, args.name), "solutions": lambda: test_solutions(ctx),
             "starter": lambda: test_starter(ctx), "repeat": lambda: test_repeat(ctx),
             "gradescope": lambda: test_gradescope(ctx), "unsafe": lambda: test_unsafe(ctx),
             "private_folders": lambda: test_private_folders(ctx),
             "targeted_build": lambda: test_targeted_build(ctx),
             "rixcheck_crash": lambda: test_rixcheck_crash(ctx)}
    tests[args.kind]()
    if problems:
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
