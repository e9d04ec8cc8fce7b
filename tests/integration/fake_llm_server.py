#!/usr/bin/env python3
"""A tiny stand-in for an OpenAI-compatible chat-completions endpoint, for llm_grouper_test.sh.

    fake_llm_server.py PORT_FILE [--lifetime S] [--hang S] [--log FILE]

Listens on 127.0.0.1 on an ephemeral port, writes the port number to PORT_FILE once it is
listening, and exits by itself after --lifetime seconds (default 60). Standard library only.

Every POST to /v1/chat/completions is checked against the request format of the `llm` grouper
(model, temperature 0, a system message, a user message with a text part holding the SVG source
and the path ids and an image_url part holding a base64 PNG data URL); a request that does not
match gets HTTP 400 naming what is wrong. The model name selects the reply:

    valid       a valid grouping of tests/data/examples/man.svg (groups and ids out of paint order)
    fenced      the same grouping inside ```json fences, with a sentence before it
    unknown_id  a grouping that names a path the SVG does not have ("left_ear")
    missing     a grouping that leaves out one path ("mouth")
    duplicate   a grouping that puts one path ("mouth") in two groups
    malformed   an answer that is not JSON (truncated)
    hang        no answer for --hang seconds (default 10), then the valid grouping
    http500     HTTP 500 with an error object
    auth        the valid grouping if "Authorization: Bearer test-secret" is sent, else HTTP 401
    echo_key    HTTP 401 whose body echoes the bearer token sent, starting at character 190 (a
                hostile server: the client's 200-character excerpt must show none of it)

A request whose instructions ask for a "best" candidate is the `llm` ranker's: it must hold a
text part listing the candidates and, per candidate, a "Candidate NAME:" text part followed by
PNG image_url frames. Its replies, by model name:

    pick_NN         {"best": "NN.mp4", "reason": ...}
    fenced_pick_NN  the same inside ```json fences
    pick_unknown    names a candidate that does not exist ("07.mp4")
    reject_NN_pick_MM  {"best": "MM.mp4", ...}
    malformed, hang, http500   as for the grouper

A request whose instructions ask whether a candidate is "viable" is the ranker's stage 1: a
text part, a "Candidate NAME:" part and PNG frames of that one candidate. Its replies:

    pick_NN, fenced_pick_NN, pick_unknown   every constraint "Yes", viable (fenced: in fences)
    reject_NN_pick_MM  candidate NN: no_3d_rotation "Partial", continuity "No", not viable;
                       the others as above
    none_viable        every constraint "No", not viable
    malformed, hang, http500   as for the grouper

A request whose instructions give the plan syntax ("verb:part") is the procedural video's `llm`
planner: a text part listing the parts ("1. NAME (...") and the motion asked for, then the
drawing as a PNG image_url; temperature 0 and an integer seed. Its replies, by model name:

    plan_valid         wave:arm_left slow, kick:leg_right  (tests/data/examples/man.svg's part names)
    plan_fenced        the same inside ``` fences, in backticks
    plan_garbage       a sentence, not a plan
    plan_unknown_part  wave:tentacle_left
    plan_unknown_verb  teleport:head
    plan_empty         an empty answer
    plan_two_lines     two plan items on two lines
    plan_auth          the valid plan if "Authorization: Bearer test-secret" is sent, else 401
    plan_echo_key      HTTP 401 echoing the bearer token sent (as echo_key)
    plan_bad_type      content [{"type": 1, ...}]: no text part
    plan_split_key     the key test-secret split over two text parts of the answer
    hang, http500      as for the grouper

With --log, every request body is appended to FILE as one JSON line.
"""
import argparse
import base64
import json
import os
import sys
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

GROUPS = {
    "groups": [
        {"name": "head", "paths": ["mouth", "face", "neck", "hair", "eye_right", "eye_left"]},
        {"name": "waving arm", "paths": ["hand_right", "upper_arm_right"]},
        {"name": "legs", "paths": ["shoe_right", "thigh_left", "thigh_right", "shoe_left"]},
        {"name": "body and left arm", "paths": ["hand_left", "torso", "belt", "upper_arm_left"]},
    ]
}
UNKNOWN = {"groups": [dict(g) for g in GROUPS["groups"]]}
UNKNOWN["groups"][0] = {"name": "head", "paths": GROUPS["groups"][0]["paths"] + ["left_ear"]}
MISSING = {"groups": [dict(g) for g in GROUPS["groups"]]}
MISSING["groups"][0] = {"name": "head", "paths": [p for p in GROUPS["groups"][0]["paths"] if p != "mouth"]}
DUPLICATE = {"groups": [dict(g) for g in GROUPS["groups"]]}
DUPLICATE["groups"][1] = {"name": "waving arm", "paths": GROUPS["groups"][1]["paths"] + ["mouth"]}
EXPECTED_IDS = ["thigh_left", "shoe_left", "torso", "hand_right", "mouth"]


def check_request(body):
    """Returns None when `body` has the expected shape, else a one-line complaint."""
    if not isinstance(body, dict):
        return "body is not a JSON object"
    if not isinstance(body.get("model"), str):
        return "model is not a string"
    if body.get("temperature") != 0:
        return "temperature is not 0"
    msgs = body.get("messages")
    if not isinstance(msgs, list) or len(msgs) != 2:
        return "messages is not a list of two"
    sys_msg, user = msgs
    if sys_msg.get("role") != "system" or not isinstance(sys_msg.get("content"), str) or not sys_msg["content"]:
        return "messages[0] is not a system message with text"
    if "groups" not in sys_msg["content"]:
        return "the instructions do not describe the answer format"
    if user.get("role") != "user" or not isinstance(user.get("content"), list) or len(user["content"]) != 2:
        return "messages[1] is not a user message with two parts"
    text, image = user["content"]
    if text.get("type") != "text" or not isinstance(text.get("text"), str):
        return "the first user part is not text"
    if "<svg" not in text["text"]:
        return "the text does not hold the SVG source"
    for pid in EXPECTED_IDS:
        if pid not in text["text"]:
            return "the text does not list path id " + pid
    problem = check_png_url(image)
    return "the second user part: " + problem if problem else None


def check_png_url(part):
    if part.get("type") != "image_url" or not isinstance(part.get("image_url"), dict):
        return "not an image_url part"
    url = part["image_url"].get("url", "")
    prefix = "data:image/png;base64,"
    if not url.startswith(prefix):
        return "the image is not a PNG data URL"
    try:
        png = base64.b64decode(url[len(prefix):], validate=True)
    except ValueError:
        return "the image is not valid base64"
    if not png.startswith(b"\x89PNG\r\n\x1a\n"):
        return "the image is not a PNG"
    return None


def instructions_mention(body, word):
    """Whether the system message (the instructions) holds `word`: tells the requests apart."""
    try:
        return word in body["messages"][0]["content"]
    except (KeyError, IndexError, TypeError):
        return False


def is_rank_request(body):
    return instructions_mention(body, '"best"')


def chat_problem(body):
    """A complaint about the parts every ranker request shares (model, temperature 0, a system
    and a user message), or None."""
    if not isinstance(body.get("model"), str) or body.get("temperature") != 0:
        return "model or temperature is wrong"
    msgs = body.get("messages")
    if not isinstance(msgs, list) or len(msgs) != 2 or msgs[1].get("role") != "user":
        return "messages is not [system, user]"
    return None


def check_rank_request(body):
    """The `llm` ranker's request shape; returns (None, candidate names) or (complaint, [])."""
    if chat_problem(body):
        return chat_problem(body), []
    parts = body["messages"][1].get("content")
    if not isinstance(parts, list) or not parts or parts[0].get("type") != "text" or "Candidates" not in parts[0]["text"]:
        return "the first user part does not list the candidates", []
    names, frames = [], 0
    for p in parts[1:]:
        if p.get("type") == "text":
            if not p["text"].startswith("Candidate ") or not p["text"].endswith(":"):
                return "a text part is not a candidate label", []
            names.append(p["text"][len("Candidate "):-1])
            frames = 0
        else:
            if not names:
                return "a frame before any candidate label", []
            problem = check_png_url(p)
            if problem:
                return problem, []
            frames += 1
    if not names:
        return "no candidates", []
    return None, names


def is_score_request(body):
    return instructions_mention(body, '"viable"')


def check_score_request(body):
    """The ranker's stage-1 shape; returns (None, candidate name) or (complaint, None)."""
    if chat_problem(body):
        return chat_problem(body), None
    parts = body["messages"][1].get("content")
    if not isinstance(parts, list) or len(parts) < 3 or parts[0].get("type") != "text" \
            or "Motion asked for" not in parts[0]["text"]:
        return "the first user part does not describe the motion", None
    label = parts[1]
    if label.get("type") != "text" or not label["text"].startswith("Candidate ") or not label["text"].endswith(":"):
        return "the second user part is not a candidate label", None
    for p in parts[2:]:
        problem = check_png_url(p)
        if problem:
            return problem, None
    return None, label["text"][len("Candidate "):-1]


PLAN = "wave:arm_left slow, kick:leg_right"
PLAN_ANSWERS = {
    "plan_valid": PLAN,
    "plan_fenced": "```\n`" + PLAN + "`\n```",
    "plan_garbage": "Sure! The man should wave his left arm slowly.",
    "plan_unknown_part": "wave:tentacle_left",
    "plan_unknown_verb": "teleport:head",
    "plan_empty": "",
    "plan_two_lines": "wave:arm_left\nkick:leg_right",
    # Content as parts: one whose type is not a string (no text in it), and the key split over
    # two text parts (scrubbed from the raw body, whole again once the parts are joined).
    "plan_bad_type": [{"type": 1, "text": "wave:arm_left"}],
    "plan_split_key": [{"type": "text", "text": "wave:arm_left test-"}, {"type": "text", "text": "secret"}],
}


def is_plan_request(body):
    return instructions_mention(body, "verb:part")


def check_plan_request(body):
    """The planner's request shape (and a seed); None or a one-line complaint."""
    if chat_problem(body):
        return chat_problem(body)
    if not isinstance(body.get("seed"), int):
        return "no integer seed"
    parts = body["messages"][1].get("content")
    if not isinstance(parts, list) or len(parts) != 2 or parts[0].get("type") != "text":
        return "the user message is not [text, image]"
    text = parts[0]["text"]
    if "Motion asked for:" not in text or "1. " not in text:
        return "the text does not list the parts and the motion"
    problem = check_png_url(parts[1])
    return "the image: " + problem if problem else None


def verdicts(yes):
    v = "Yes" if yes else "No"
    return {"no_3d_rotation": v, "no_new_elements": v, "flat_colours": v, "continuity": v,
            "viable": yes, "reason": "fake stage 1"}


def completion(content):
    return {
        "id": "chatcmpl-fake",
        "object": "chat.completion",
        "created": int(time.time()),
        "model": "fake",
        "choices": [{"index": 0, "message": {"role": "assistant", "content": content}, "finish_reason": "stop"}],
    }


class Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"

    def log_message(self, *args):  # quiet
        pass

    def reply(self, status, obj):
        data = (obj if isinstance(obj, str) else json.dumps(obj)).encode()
        try:
            self.send_response(status)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(data)))
            self.end_headers()
            self.wfile.write(data)
        except (BrokenPipeError, ConnectionResetError):
            pass  # the client gave up (the hang case)

    def do_POST(self):
        length = int(self.headers.get("Content-Length") or 0)
        raw = self.rfile.read(length)
        if self.path != "/v1/chat/completions":
            return self.reply(404, {"error": {"message": "no such path " + self.path}})
        try:
            body = json.loads(raw)
        except ValueError:
            return self.reply(400, {"error": {"message": "the request body is not JSON"}})
        if self.server.log_file:
            with self.server.lock, open(self.server.log_file, "a") as f:
                f.write(json.dumps({"headers": dict(self.headers), "body": body}) + "\n")
        model = body.get("model")
        if is_plan_request(body):
            return self.plan_reply(body, model)
        if is_score_request(body) and model not in ("malformed", "hang", "http500"):
            problem, name = check_score_request(body)
            if problem:
                return self.reply(400, {"error": {"message": problem}})
            answer = verdicts(model != "none_viable")
            if model.startswith("reject_") and name == model.split("_")[1] + ".mp4":
                answer = dict(answer, no_3d_rotation="Partial", continuity="No", viable=False,
                              reason="the arm turns in depth")
            text = json.dumps(answer)
            if model.startswith("fenced_"):
                text = "Verdict:\n```json\n" + text + "\n```"
            return self.reply(200, completion(text))
        if is_rank_request(body) and model.startswith("reject_"):
            problem, _ = check_rank_request(body)
            if problem:
                return self.reply(400, {"error": {"message": problem}})
            return self.reply(200, completion(json.dumps({"best": model.split("_")[3] + ".mp4", "reason": "fake judge"})))
        if is_rank_request(body):
            problem, _ = check_rank_request(body)
            if problem:
                return self.reply(400, {"error": {"message": problem}})
            if model.startswith("pick_") and model != "pick_unknown":
                return self.reply(200, completion(json.dumps({"best": model[5:] + ".mp4", "reason": "fake judge"})))
            if model.startswith("fenced_pick_"):
                best = {"best": model[12:] + ".mp4", "reason": "fake judge"}
                return self.reply(200, completion("My choice:\n```json\n" + json.dumps(best) + "\n```"))
            if model == "pick_unknown":
                return self.reply(200, completion(json.dumps({"best": "07.mp4", "reason": "fake judge"})))
        problem = None if is_rank_request(body) or is_score_request(body) else check_request(body)
        if problem:
            return self.reply(400, {"error": {"message": problem}})
        if model == "valid":
            return self.reply(200, completion(json.dumps(GROUPS)))
        if model == "fenced":
            return self.reply(200, completion("Here are the parts:\n```json\n" + json.dumps(GROUPS, indent=2) + "\n```\n"))
        if model == "unknown_id":
            return self.reply(200, completion(json.dumps(UNKNOWN)))
        if model == "missing":
            return self.reply(200, completion(json.dumps(MISSING)))
        if model == "duplicate":
            return self.reply(200, completion(json.dumps(DUPLICATE)))
        if model == "malformed":
            return self.reply(200, completion(json.dumps(GROUPS)[:40]))
        if model == "hang":
            time.sleep(self.server.hang)
            return self.reply(200, completion(json.dumps(GROUPS)))
        if model == "http500":
            return self.reply(500, {"error": {"message": "the fake model fell over"}})
        if model == "echo_key":
            sent = (self.headers.get("Authorization") or "")[len("Bearer "):]
            return self.reply(401, "x" * 190 + sent + " is not a key we know")
        if model == "auth":
            if self.headers.get("Authorization") != "Bearer test-secret":
                return self.reply(401, {"error": {"message": "missing or wrong API key"}})
            return self.reply(200, completion(json.dumps(GROUPS)))
        return self.reply(404, {"error": {"message": "unknown model " + model}})


    def plan_reply(self, body, model):
        problem = check_plan_request(body)
        if problem:
            return self.reply(400, {"error": {"message": problem}})
        if model in PLAN_ANSWERS:
            return self.reply(200, completion(PLAN_ANSWERS[model]))
        if model == "plan_auth":
            if self.headers.get("Authorization") != "Bearer test-secret":
                return self.reply(401, {"error": {"message": "missing or wrong API key"}})
            return self.reply(200, completion(PLAN))
        if model == "plan_echo_key":
            sent = (self.headers.get("Authorization") or "")[len("Bearer "):]
            return self.reply(401, "x" * 190 + sent + " is not a key we know")
        if model == "hang":
            time.sleep(self.server.hang)
            return self.reply(200, completion(PLAN))
        if model == "http500":
            return self.reply(500, {"error": {"message": "the fake model fell over"}})
        return self.reply(404, {"error": {"message": "unknown model " + str(model)}})


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("port_file")
    ap.add_argument("--lifetime", type=float, default=60)
    ap.add_argument("--hang", type=float, default=10)
    ap.add_argument("--log", default="")
    a = ap.parse_args()
    ThreadingHTTPServer.daemon_threads = True
    ThreadingHTTPServer.block_on_close = False
    server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    server.hang = a.hang
    server.log_file = a.log
    server.lock = threading.Lock()
    tmp = a.port_file + ".tmp"
    with open(tmp, "w") as f:
        f.write(str(server.server_address[1]))
    os.replace(tmp, a.port_file)
    threading.Timer(a.lifetime, server.shutdown).start()
    server.serve_forever(poll_interval=0.1)
    server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
