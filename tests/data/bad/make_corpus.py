#!/usr/bin/env python3
"""Regenerates the bad-input corpus (tests/data/bad/) and its manifest.json from the repository's
own good files: the sample project (resources/sample/shelf_1_panda) and the bundled benchmark
data (resources/gtamp). Run from anywhere; needs ffmpeg for the videos. The output is committed;
the tests read the stored files, not this script."""
import json
import os
import random
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
SAMPLE = os.path.join(ROOT, "resources", "sample", "shelf_1_panda")
GTAMP = os.path.join(ROOT, "resources", "gtamp")

entries = []


def write(rel, data):
    path = os.path.join(HERE, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def read(path):
    with open(path, "rb") as f:
        return f.read()


def dumps(j):
    return json.dumps(j, indent=1, allow_nan=True) + "\n"


def add(rel, kind, what, args, expect, data_dir=None, gui=None):
    """One corpus file: `args` is the CLI command line ({file}: this file, {data}: a copy of the
    benchmark data with `data_dir`'s files replaced, {sample}: the sample project folder, {work}:
    a scratch folder); `expect`: substrings of the one-line error. `gui`: how the GUI opens it
    (project: opened as the project; video/camera/markers: a copy of the sample project pointing at it)."""
    e = {"file": rel, "kind": kind, "what": what, "args": args, "expect": expect}
    if data_dir:
        e["data_dir"] = data_dir
    if gui:
        e["gui"] = gui
    entries.append(e)


EXTRACT = ["extract", "{file}", "--scene", "{sample}/markers.json", "--camera", "{sample}/camera.json", "--out",
           "{work}/demo.json"]
CHECK = ["check", "--task", "shelf_1", "--robot", "panda", "--pose", "0", "--json", "--seconds", "0.1", "--data-dir",
         "{data}"]

# ---- videos -------------------------------------------------------------------------------
video = read(os.path.join(SAMPLE, "video.mp4"))
tmp = os.path.join(HERE, "tmp_small.mp4")
subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", os.path.join(SAMPLE, "video.mp4"), "-t", "0.5", "-vf",
                "scale=320:-2", "-an", "-c:v", "libx264", "-movflags", "+faststart", tmp], check=True)
small = read(tmp)
os.remove(tmp)
write("video/empty.mp4", b"")
add("video/empty.mp4", "video", "empty file", EXTRACT, ["{file}"], gui="video")
random.seed(17)
write("video/random_bytes.mp4", bytes(random.getrandbits(8) for _ in range(4096)))
add("video/random_bytes.mp4", "video", "4 KiB of random bytes", EXTRACT, ["{file}"], gui="video")
write("video/text.mp4", "this is not a video\n")
add("video/text.mp4", "video", "a text file named .mp4", EXTRACT, ["{file}"], gui="video")
write("video/header_only.mp4", small[:1024])
add("video/header_only.mp4", "video", "the first KiB of an mp4 (moov header cut)", EXTRACT, ["{file}"], gui="video")
# moov first (faststart), so a truncated file has its index but loses frames
write("video/truncated_half.mp4", small[: len(small) // 2])
add("video/truncated_half.mp4", "video", "an mp4 cut at half its length", EXTRACT, ["{file}", "frame"], gui="video")
tmp = os.path.join(HERE, "tmp_audio.mp4")
subprocess.run(["ffmpeg", "-v", "error", "-y", "-f", "lavfi", "-i", "sine=d=0.2", "-c:a", "aac", tmp], check=True)
write("video/audio_only.mp4", read(tmp))
os.remove(tmp)
add("video/audio_only.mp4", "video", "an mp4 with only an audio stream", EXTRACT, ["{file}", "video stream"], gui="video")
corrupt = bytearray(small)
random.seed(3)
for i in range(len(corrupt) // 3, len(corrupt)):
    corrupt[i] = random.getrandbits(8)
write("video/corrupt_tail.mp4", bytes(corrupt))
add("video/corrupt_tail.mp4", "video", "an mp4 whose last two thirds are random bytes", EXTRACT, ["{file}", "frame"],
    gui="video")

# ---- URDF (robot model), fed through check with a copy of the benchmark data ---------------
urdf = read(os.path.join(GTAMP, "robots", "franka_panda", "panda.urdf")).decode()
URDF_AT = "robots/franka_panda/panda.urdf"


def bad_urdf(name, what, text, expect, extra=None):
    assert text != urdf, name
    write("urdf/" + name, text)
    dd = {URDF_AT: "urdf/" + name}
    if extra:
        dd.update(extra)
    add("urdf/" + name, "urdf", what, CHECK, ["panda.urdf"] + expect, data_dir=dd)


def once(text, a, b):
    assert text.count(a) >= 1, a
    return text.replace(a, b, 1)


bad_urdf("missing_link.urdf", "a joint's child link is not defined",
         once(urdf, '<link name="panda_link3">', '<link name="panda_link3_gone">'), ["panda_link3"])
bad_urdf("cycle.urdf", "joints form a cycle (link0 is a child of link7)",
         once(urdf, "</robot>", '<joint name="loop" type="fixed"><parent link="panda_link7"/><child link="panda_link0"/></joint>\n</robot>'),
         ["cycle", "panda_link0"])
bad_urdf("unknown_parent.urdf", "a joint names an unknown parent link",
         once(urdf, '<parent link="panda_link2"/>', '<parent link="panda_link_nope"/>'), ["panda_link_nope"])
bad_urdf("not_xml.urdf", "not XML", "robot: panda\nlinks: [panda_link0]\n", [])
bad_urdf("truncated.urdf", "cut at half its length", urdf[: len(urdf) // 2], [])
bad_urdf("nan_origin.urdf", "NaN in a joint origin",
         once(urdf, '<origin rpy="0 0 0" xyz="0 0 0.333"/>', '<origin rpy="0 0 0" xyz="0 nan 0.333"/>'), ["panda_joint1"])
bad_urdf("missing_mesh.urdf", "a collision mesh that does not exist",
         once(urdf, '"meshes/collision/link4.stl"', '"meshes/collision/link4_missing.stl"'), ["link4_missing.stl"])
bad_urdf("empty_mesh.urdf", "a collision mesh that is an empty file",
         once(urdf, '"meshes/collision/link4.stl"', '"meshes/collision/empty.stl"'), ["empty.stl"],
         {"robots/franka_panda/meshes/collision/empty.stl": "mesh/empty.stl"})
bad_urdf("garbage_mesh.urdf", "a collision mesh of random bytes",
         once(urdf, '"meshes/collision/link4.stl"', '"meshes/collision/garbage.stl"'), ["garbage.stl"],
         {"robots/franka_panda/meshes/collision/garbage.stl": "mesh/garbage.stl"})
write("mesh/empty.stl", b"")
random.seed(5)
write("mesh/garbage.stl", bytes(random.getrandbits(8) for _ in range(300)))

# ---- SRDF ---------------------------------------------------------------------------------
srdf = read(os.path.join(GTAMP, "robots", "franka_panda", "panda.srdf")).decode()
SRDF_AT = "robots/franka_panda/panda.srdf"


def bad_srdf(name, what, text, expect):
    assert text != srdf, name
    write("srdf/" + name, text)
    add("srdf/" + name, "srdf", what, CHECK, ["panda.srdf"] + expect, data_dir={SRDF_AT: "srdf/" + name})


# (A robot's disable_collisions naming an unknown link is accepted: the upstream ur5.srdf names
# ee_link, which ur5.urdf does not have; such a pair disables nothing.)
bad_srdf("unknown_gripper_link.srdf", "the gripper names an unknown link",
         once(srdf, '<link name="panda_hand"/>', '<link name="panda_palm"/>'), ["panda_palm"])
bad_srdf("truncated.srdf", "cut at half its length", srdf[: len(srdf) // 2], [])
obj_srdf = read(os.path.join(GTAMP, "objects", "ycbv", "srdf", "obj_000002.srdf")).decode()
OBJ_SRDF_AT = "objects/ycbv/srdf/obj_000002.srdf"
write("srdf/object_unknown_handle_link.srdf", once(obj_srdf, '<link name="base_link"/>', '<link name="lid_link"/>'))
add("srdf/object_unknown_handle_link.srdf", "srdf", "an object's handle on a link its URDF does not have", CHECK,
    ["obj_000002.srdf", "handle 'handleZpx' link", "lid_link"], data_dir={OBJ_SRDF_AT: "srdf/object_unknown_handle_link.srdf"})
shelf_srdf = read(os.path.join(GTAMP, "furniture", "shelf_1_1_shelf.srdf")).decode()
SHELF_SRDF_AT = "furniture/shelf_1_1_shelf.srdf"
write("srdf/furniture_unknown_contact_link.srdf", once(shelf_srdf, '<link name="top_desk"/>', '<link name="top_desk_gone"/>'))
add("srdf/furniture_unknown_contact_link.srdf", "srdf", "a furniture contact surface on a link its URDF does not have",
    CHECK, ["shelf_1_1_shelf.srdf", "contact 'top_shelf_surface' link", "top_desk_gone"],
    data_dir={SHELF_SRDF_AT: "srdf/furniture_unknown_contact_link.srdf"})

# ---- benchmark task (object poses) -------------------------------------------------------
task = json.loads(read(os.path.join(GTAMP, "tasks", "shelf_1.json")))
TASK_AT = "tasks/shelf_1.json"


def bad_task(name, what, j, expect):
    write("task/" + name, j if isinstance(j, str) else json.dumps(j, separators=(",", ":")))
    add("task/" + name, "task", what, CHECK, ["shelf_1.json"] + expect, data_dir={TASK_AT: "task/" + name})


t = json.loads(json.dumps(task))
t["objects_poses"][0][3][0][3] = None  # what a NaN becomes in JSON
bad_task("nan_pose.json", "NaN (null) in an object pose", t, ["objects_poses[0][3]"])
t = json.loads(json.dumps(task))
t["objects_poses"][1][7][0][0] *= 2.0
bad_task("non_rigid_pose.json", "an object pose whose rotation is scaled", t, ["objects_poses[1][7]"])
text = json.dumps(task, separators=(",", ":"))
bad_task("truncated.json", "cut at 60 % of its length", text[: len(text) * 6 // 10], [])

# ---- camera -------------------------------------------------------------------------------
camera = json.loads(read(os.path.join(SAMPLE, "camera.json")))
CAM = ["extract", "{sample}/video.mp4", "--scene", "{sample}/markers.json", "--camera", "{file}", "--out",
       "{work}/demo.json"]


def bad_camera(name, what, j, expect):
    write("camera/" + name, j if isinstance(j, str) else dumps(j))
    add("camera/" + name, "camera", what, CAM, ["{file}"] + expect, gui="camera")


c = json.loads(json.dumps(camera))
c["intrinsics"]["fx"] = 0.0
bad_camera("singular_fx0.json", "fx = 0: a singular camera matrix", c, ["fx"])
c = json.loads(json.dumps(camera))
c["world_T_camera"]["q"] = [0, 0, 0, 0]
bad_camera("zero_quaternion.json", "world_T_camera with a zero quaternion", c, ["world_T_camera"])
c = json.loads(json.dumps(camera))
c["intrinsics"]["cy"] = None
bad_camera("nan_cy.json", "cy is NaN (null)", c, ["cy"])
text = read(os.path.join(SAMPLE, "camera.json")).decode()
bad_camera("truncated.json", "cut at half its length", text[: len(text) // 2], [])
bad_camera("singular.yaml", "OpenCV YAML whose camera matrix is all zeros",
           "%YAML:1.0\n---\nimage_width: 1280\nimage_height: 720\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n"
           "   dt: d\n   data: [ 0., 0., 0., 0., 0., 0., 0., 0., 0. ]\n"
           "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n   data: [ 0., 0., 0., 0., 0. ]\n",
           ["camera_matrix"])

# ---- marker scene ------------------------------------------------------------------------
markers = json.loads(read(os.path.join(SAMPLE, "markers.json")))
MARK = ["extract", "{sample}/video.mp4", "--scene", "{file}", "--camera", "{sample}/camera.json", "--out",
        "{work}/demo.json"]


def bad_markers(name, what, j, expect):
    write("markers/" + name, j if isinstance(j, str) else dumps(j))
    add("markers/" + name, "markers", what, MARK, ["{file}"] + expect)  # the GUI reads it only to extract


m = json.loads(json.dumps(markers))
m["objects"][0]["markers"][1]["object_T_marker"]["t"][1] = None
bad_markers("nan_marker_pose.json", "NaN (null) in a marker's pose", m, ["object_T_marker"])
m = json.loads(json.dumps(markers))
m["objects"][0]["markers"][0]["size"] = -0.07
bad_markers("negative_size.json", "a negative marker size", m, ["size"])
text = read(os.path.join(SAMPLE, "markers.json")).decode()
bad_markers("truncated.json", "cut at half its length", text[: len(text) // 2], [])

# ---- BOP CSV (6D pose estimates) ----------------------------------------------------------
BOP = ["extract", "{sample}/video.mp4", "--scene", "{sample}/markers.json", "--camera", "{sample}/camera.json",
       "--detections", "{file}", "--out", "{work}/demo.json"]
R = "1 0 0 0 1 0 0 0 1"
good_row = "1,0,2,0.9," + R + ",100 200 900,0.1\n"
header = "scene_id,im_id,obj_id,score,R,t,time\n"


def bad_bop(name, what, text, expect):
    write("bop/" + name, text)
    add("bop/" + name, "bop", what, BOP, ["{file}"] + expect)


bad_bop("missing_time_column.csv", "rows with 6 columns (no time)", header + good_row + "1,1,2,0.9," + R + ",100 200 900\n",
        ["line 3"])
bad_bop("extra_column.csv", "a header with 8 columns", "scene_id,im_id,obj_id,score,R,t,time,extra\n" + good_row, ["line 1"])
bad_bop("short_rotation.csv", "R with 8 numbers", header + "1,0,2,0.9,1 0 0 0 1 0 0 0,100 200 900,0.1\n", ["R"])
bad_bop("non_rigid_rotation.csv", "R scaled by 2 (not a rotation)",
        header + "1,0,2,0.9,2 0 0 0 2 0 0 0 2,100 200 900,0.1\n", ["R"])
bad_bop("nan_translation.csv", "t holds nan", header + "1,0,2,0.9," + R + ",100 nan 900,0.1\n", ["t"])
bad_bop("text_ids.csv", "im_id is not an integer", header + "1,first,2,0.9," + R + ",100 200 900,0.1\n", ["im_id"])

# ---- hand detections ----------------------------------------------------------------------
HANDS = ["extract", "{sample}/video.mp4", "--scene", "{sample}/markers.json", "--camera", "{sample}/camera.json",
         "--hands", "{file}", "--out", "{work}/demo.json"]
hands_good = {"format": "demoplan-hand-detections", "version": 1,
              "frames": [{"frame": 0, "hand_dets": [[10, 20, 110, 140, 0.98, 3, 0.1, 0.2, 0.3, 1]], "obj_dets": []}]}


def bad_hands(name, what, j, expect):
    write("hands/" + name, j if isinstance(j, str) else dumps(j))
    add("hands/" + name, "hands", what, HANDS, ["{file}"] + expect)


h = json.loads(json.dumps(hands_good))
h["frames"][0]["hand_dets"][0] = h["frames"][0]["hand_dets"][0][:6]
bad_hands("short_hand_row.json", "a hand row with 6 columns instead of 10", h, ["frames[0]", "hand_dets[0]"])
h = json.loads(json.dumps(hands_good))
h["frames"][0]["hand_dets"][0][5] = 7
bad_hands("bad_contact_state.json", "contact state column 7 (must be 0..4)", h, ["frames[0]", "hand_dets[0][5]"])
h = json.loads(json.dumps(hands_good))
h["frames"][0]["obj_dets"] = [[1, 2, 3]]
bad_hands("short_object_row.json", "an object row with 3 columns", h, ["frames[0]", "obj_dets[0]"])
h = json.loads(json.dumps(hands_good))
h["frames"][0]["frame"] = -4
bad_hands("negative_frame.json", "frame -4", h, ["frames[0]", "frame"])

# ---- project and demonstration files truncated at every 10 % ------------------------------
project_text = read(os.path.join(SAMPLE, "shelf_1_panda.demoplan"))
project = json.loads(project_text)
demo_text = dumps(project["demonstration"]).encode()
write("demonstration/good.json.in", demo_text)  # the untruncated file, for reference (not part of the corpus)
INSPECT = ["inspect", "{file}", "--data-dir", "{gtamp}"]
EVAL = ["evaluate", "{file}", "--truth", "{here}/demonstration/good.json.in", "--data-dir", "{gtamp}"]

for k in range(10):
    n = len(project_text) * k // 10
    rel = "project/truncated_%02d.demoplan" % (k * 10)
    write(rel, project_text[:n])
    add(rel, "project", "the sample project cut at %d %% of its length (%d bytes)" % (k * 10, n), INSPECT, ["{file}"],
        gui="project")
    n = len(demo_text) * k // 10
    rel = "demonstration/truncated_%02d.json" % (k * 10)
    write(rel, demo_text[:n])
    add(rel, "demonstration", "a demonstration cut at %d %% of its length (%d bytes)" % (k * 10, n), EVAL, ["{file}"])

p = json.loads(json.dumps(project))
p["demonstration"]["events"][1]["poses"]["YCBV_05"][2][3] = None
write("project/nan_pose.demoplan", dumps(p))
add("project/nan_pose.demoplan", "project", "NaN (null) in a demonstrated pose", INSPECT,
    ["{file}", "events[1]"], gui="project")
p = json.loads(json.dumps(project))
p["demonstration"]["events"][0]["poses"]["YCBV_02"][0][0] = 3.0
write("project/non_rigid_pose.demoplan", dumps(p))
add("project/non_rigid_pose.demoplan", "project", "a demonstrated pose whose rotation is not orthonormal", INSPECT,
    ["{file}", "events[0]"], gui="project")
p = json.loads(json.dumps(project))
p["tracker_corrections"] = [{"id": "YCBV_99", "frame": 40, "world_T_object": p["demonstration"]["events"][0]["poses"]["YCBV_02"]}]
write("project/correction_unknown_part.demoplan", dumps(p))
add("project/correction_unknown_part.demoplan", "project", "a part placed again for the tracker that is not in the demonstration",
    INSPECT, ["{file}", "tracker_corrections[0].id"], gui="project")
d = json.loads(json.dumps(project["demonstration"]))
d["events"][0]["poses"]["YCBV_02"][1][3] = None
write("demonstration/nan_pose.json", dumps(d))
add("demonstration/nan_pose.json", "demonstration", "NaN (null) in a pose", EVAL, ["{file}", "events[0]"], gui="demonstration")
d = json.loads(json.dumps(project["demonstration"]))
d["events"][2]["poses"]["YCBV_05"][0][1] = 0.5
write("demonstration/non_rigid_pose.json", dumps(d))
add("demonstration/non_rigid_pose.json", "demonstration", "a pose whose rotation is not orthonormal", EVAL,
    ["{file}", "events[2]"], gui="demonstration")
d = json.loads(json.dumps(project["demonstration"]))
d["events"][1]["frame"] = -3
write("demonstration/negative_frame.json", dumps(d))
add("demonstration/negative_frame.json", "demonstration", "an event at frame -3", EVAL, ["{file}", "events[1]", "frame"],
    gui="demonstration")

with open(os.path.join(HERE, "manifest.json"), "w") as f:
    json.dump({"note": "written by make_corpus.py; see README.md", "entries": entries}, f, indent=1)
    f.write("\n")
print(len(entries), "entries")
