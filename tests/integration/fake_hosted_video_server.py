#!/usr/bin/env python3
"""A stand-in for hosted image-to-video APIs, for hosted_video_test.sh. Standard library only.

    fake_hosted_video_server.py PORT_FILE --video FILE --key KEY [--lifetime S] [--log FILE]

Two servers on 127.0.0.1: the API (its port written to PORT_FILE once listening) and a
"storage" host on another port (another origin), where finished videos are served, as cloud
APIs hand out download links on storage hosts. Both exit after --lifetime seconds (default 60).
The request and reply shapes follow the providers' documentation (third_party_notes.md):

Gemini API (Veo), key in the header x-goog-api-key (else HTTP 400 INVALID_ARGUMENT with reason
API_KEY_INVALID, the message echoing the key sent: a hostile variant, to test scrubbing):
    POST /v1beta/models/MODEL:predictLongRunning   {"instances": [{"prompt", "image":
         {"bytesBase64Encoded": PNG, "mimeType": "image/png"}}], "parameters": {...}}
         -> {"name": "models/MODEL/operations/ID"}      (400 naming a malformed field)
    GET  /v1beta/models/MODEL/operations/ID -> {"name", "done": false} ... then done with
         response.generateVideoResponse.generatedSamples[0].video.uri, or an error
    GET  /v1beta/files/ID:download?alt=media -> 302 to the storage host
  MODEL picks the behaviour:
    veo-ok          done on the 2nd poll
    veo-slow        done 2.5 s after the submit (the client must keep polling)
    veo-hang        never done
    veo-error       done with {"error": {"code": 13, "message": "Internal error..."}}
    veo-mixed       as veo-ok, except that odd seeds end with the error above
    veo-ratelimit   the first submit for this model gets 429 RESOURCE_EXHAUSTED, Retry-After: 1
    veo-notvideo    the storage host serves an HTML page instead of the video

fal.ai queue, key as "Authorization: Key KEY" (else 401 {"detail": ...}):
    POST /fal-ai/MODE  {"prompt", "image_url": PNG data URL, "seed", ...}
         -> {"request_id", "status_url", "response_url", "cancel_url"}
    GET  /fal-ai/requests/ID/status -> {"status": "IN_QUEUE"}, "IN_PROGRESS", "COMPLETED"
    GET  /fal-ai/requests/ID -> {"video": {"url": storage URL}, "seed"}
  MODE: wan-i2v (ok), ratelimit (the first status poll gets 429 with Retry-After: 1)

Replicate predictions, key as "Authorization: Bearer KEY" (else 401 {"detail": ...}):
    POST /v1/models/OWNER/MODE/predictions  {"input": {"image", "prompt", "seed", ...}}
         -> {"id", "status": "starting", "urls": {"get", "cancel"}, "output": null, "error": null}
    GET  /v1/predictions/ID -> "processing", then "succeeded" with "output": storage URL
  MODE: wan-2.2-i2v-fast (ok), failed (status "failed", error "CUDA out of memory")

Storage host: GET /blob/ID.mp4 -> the bytes of --video (403 if an API key header arrives).

Hostile variants, http-job shaped, any "Authorization: Bearer KEY" accepted (hosted_video_hostile_test.sh):
    POST /evil/MODE -> {"id", "status": "queued", "status_url": API/evil/MODE/status}
    GET  /evil/MODE/status -> {"status": "done", "video_url": API/evil/MODE/video}
    GET  /evil/MODE/video -> the bytes of --video, unless MODE says otherwise
  MODE:
    redirect-file           the video answers 302 to file:///etc/passwd
    redirect-dict           the video answers 302 to dict://127.0.0.1:TRAP/info, TRAP a raw TCP
                            listener that logs {"host": "trap"} for every connection it accepts
    redirect-absolute-path  the video answers 302 to "/evil/redirect-absolute-path/video.mp4"
    redirect-relative-path  the video answers 302 to "video.mp4" (-> /evil/MODE/video.mp4)
    redirect-other-host     the video answers 302 to http://localhost:STORAGE/blob/ID.mp4 (the
                            storage host by another name)
    status-file             the submit reply's status_url is file:///etc/passwd
    echo-key                the submit answers 500 {"detail": 190 "x", then the key sent, ...}
    echo-key-encoded        the same with the key percent-encoded
    endless-status          the status poll answers 200 with a JSON body that never ends
    endless-video           the video never ends
    big-status              the status poll announces a 100 MiB body (Content-Length)

With --log, every request (and every 429 the fal queue sends, as method "429") is appended to FILE as one JSON line:
{"t": seconds, "host": "api"|"storage", "method", "path", "headers", "body"} (body parsed as
JSON when it is; image data replaced by its size to keep the log small).
"""
import argparse
import base64
import json
import os
import socket
import sys
import threading
import time
import urllib.parse
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

lock = threading.Lock()
args = None
state = {"ops": {}, "jobs": {}, "counter": 100, "ratelimited": set(), "storage_port": 0, "trap_port": 0}


def log(entry):
    if args.log:
        with lock, open(args.log, "a") as f:
            f.write(json.dumps(entry) + "\n")


def png_problem(b64):
    try:
        data = base64.b64decode(b64, validate=True)
    except (ValueError, TypeError):
        return "not valid base64"
    return None if data.startswith(b"\x89PNG\r\n\x1a\n") else "not a PNG"


def shrink(body):
    """The body for the log: images replaced by their length."""
    if isinstance(body, dict):
        return {k: ("<%d chars>" % len(v) if isinstance(v, str) and len(v) > 200 else shrink(v)) for k, v in body.items()}
    if isinstance(body, list):
        return [shrink(v) for v in body]
    return body


def polled(table, key):
    """state[table][key] with one more poll counted, or None."""
    with lock:
        entry = state[table].get(key)
        if entry:
            entry["polls"] += 1
        return entry


def next_id():
    with lock:
        state["counter"] += 1
        return "id%d" % state["counter"]


class Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"
    host_name = "api"

    def log_message(self, *a):
        pass

    def reply(self, status, body, content_type="application/json", headers=()):
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
        try:
            self.send_response(status)
            self.send_header("Content-Type", content_type)
            self.send_header("Content-Length", str(len(data)))
            for k, v in headers:
                self.send_header(k, v)
            self.end_headers()
            self.wfile.write(data)
        except (BrokenPipeError, ConnectionResetError):
            pass

    def base(self):
        return "http://127.0.0.1:%d" % self.server.server_address[1]

    def storage(self, name):
        return "http://127.0.0.1:%d/blob/%s" % (state["storage_port"], name)

    def record(self, body):
        log({"t": time.time(), "host": self.host_name, "method": self.command, "path": self.path,
             "headers": dict(self.headers), "body": shrink(body)})

    def read_body(self):
        raw = self.rfile.read(int(self.headers.get("Content-Length") or 0))
        try:
            return json.loads(raw) if raw else None
        except ValueError:
            return raw.decode("latin-1")

    # ---- Gemini API -------------------------------------------------------------------------
    def google_key_ok(self):
        if self.headers.get("x-goog-api-key") == args.key:
            return True
        got = self.headers.get("x-goog-api-key") or ""
        self.reply(400, {"error": {"code": 400, "message": "API key not valid. Please pass a valid API key. (" + got + ")",
                                   "status": "INVALID_ARGUMENT",
                                   "details": [{"@type": "type.googleapis.com/google.rpc.ErrorInfo",
                                                "reason": "API_KEY_INVALID", "domain": "googleapis.com"}]}})
        return False

    def veo_submit(self, model, body):
        def bad(msg):
            return self.reply(400, {"error": {"code": 400, "message": msg, "status": "INVALID_ARGUMENT"}})
        if not isinstance(body, dict) or not isinstance(body.get("instances"), list) or len(body["instances"]) != 1:
            return bad("instances must be a list of one")
        inst = body["instances"][0]
        if not isinstance(inst.get("prompt"), str) or not inst["prompt"]:
            return bad("instances[0].prompt is missing")
        image = inst.get("image")
        if not isinstance(image, dict) or image.get("mimeType") != "image/png":
            return bad("instances[0].image.mimeType must be image/png")
        problem = png_problem(image.get("bytesBase64Encoded"))
        if problem:
            return bad("instances[0].image.bytesBase64Encoded is " + problem)
        params = body.get("parameters", {})
        if params.get("aspectRatio", "16:9") not in ("16:9", "9:16"):
            return bad("parameters.aspectRatio must be 16:9 or 9:16")
        if params.get("durationSeconds", 8) not in (4, 6, 8):
            return bad("parameters.durationSeconds must be 4, 6 or 8")
        if model == "veo-ratelimit":
            with lock:
                first = model not in state["ratelimited"]
                state["ratelimited"].add(model)
            if first:
                return self.reply(429, {"error": {"code": 429, "message": "Resource has been exhausted (e.g. check quota).",
                                                  "status": "RESOURCE_EXHAUSTED"}}, headers=[("Retry-After", "1")])
        oid = next_id()
        name = "models/%s/operations/%s" % (model, oid)
        with lock:
            state["ops"][name] = {"model": model, "polls": 0, "t0": time.time(), "seed": params.get("seed", 0)}
        return self.reply(200, {"name": name})

    def veo_poll(self, name):
        op = polled("ops", name)
        if not op:
            return self.reply(404, {"error": {"code": 404, "message": "operation not found", "status": "NOT_FOUND"}})
        model = op["model"]
        pending = {"name": name, "done": False}
        if model == "veo-hang" or (model == "veo-slow" and time.time() - op["t0"] < 2.5) or \
                (model != "veo-slow" and op["polls"] < 2):
            return self.reply(200, pending)
        if model == "veo-error" or (model == "veo-mixed" and op["seed"] % 2 == 1):
            return self.reply(200, {"name": name, "done": True,
                                    "error": {"code": 13, "message": "Internal error while generating the video."}})
        fid = name.rsplit("/", 1)[1] + ("-html" if model == "veo-notvideo" else "")
        return self.reply(200, {"name": name, "done": True, "response": {
            "@type": "type.googleapis.com/google.ai.generativelanguage.v1beta.PredictLongRunningResponse",
            "generateVideoResponse": {"generatedSamples": [
                {"video": {"uri": self.base() + "/v1beta/files/%s:download?alt=media" % fid}}]}}})

    # ---- fal.ai queue -----------------------------------------------------------------------
    def key_ok(self, header, expected, refusal):
        """Whether `header` holds `expected`; else answers 401 with the provider's `refusal`."""
        if self.headers.get(header) == expected:
            return True
        self.reply(401, refusal)
        return False

    def fal_key_ok(self):
        return self.key_ok("Authorization", "Key " + args.key, {"detail": "Invalid or missing API key"})

    def fal_submit(self, mode, body):
        if not isinstance(body, dict) or not isinstance(body.get("prompt"), str):
            return self.reply(422, {"detail": [{"loc": ["body", "prompt"], "msg": "field required"}]})
        url = body.get("image_url", "")
        if not isinstance(url, str) or not url.startswith("data:image/png;base64,") or png_problem(url[22:]):
            return self.reply(422, {"detail": [{"loc": ["body", "image_url"], "msg": "not a PNG data URI"}]})
        if not isinstance(body.get("seed"), int):
            return self.reply(422, {"detail": [{"loc": ["body", "seed"], "msg": "not an integer"}]})
        rid = next_id()
        with lock:
            state["jobs"][rid] = {"mode": mode, "polls": 0}
        b = self.base() + "/fal-ai/requests/" + rid
        return self.reply(200, {"request_id": rid, "status_url": b + "/status", "response_url": b,
                                "cancel_url": b + "/cancel", "queue_position": 0})

    def fal_get(self, rest):
        rid, _, tail = rest.partition("/")
        with lock:
            job = state["jobs"].get(rid)
        if job and tail == "status":
            job = polled("jobs", rid)
        if not job:
            return self.reply(404, {"detail": "Request not found"})
        if tail == "status":
            if job["mode"] == "ratelimit" and job["polls"] == 1:
                log({"t": time.time(), "host": "api", "method": "429", "path": self.path, "headers": {}, "body": None})
                return self.reply(429, {"detail": "Too many requests"}, headers=[("Retry-After", "1")])
            status = ["IN_QUEUE", "IN_PROGRESS"][job["polls"] - 1] if job["polls"] <= 2 else "COMPLETED"
            return self.reply(200, {"status": status, "request_id": rid})
        return self.reply(200, {"video": {"url": self.storage(rid + ".mp4"), "content_type": "video/mp4"}, "seed": 1})

    # ---- Replicate --------------------------------------------------------------------------
    def replicate_key_ok(self):
        return self.key_ok("Authorization", "Bearer " + args.key, {
            "title": "Unauthenticated", "detail": "You did not pass a valid authentication token", "status": 401})

    def replicate_submit(self, mode, body):
        inp = body.get("input") if isinstance(body, dict) else None
        if not isinstance(inp, dict) or not isinstance(inp.get("prompt"), str):
            return self.reply(422, {"detail": "input.prompt is required", "status": 422})
        img = inp.get("image", "")
        if not isinstance(img, str) or not img.startswith("data:image/png;base64,") or png_problem(img[22:]):
            return self.reply(422, {"detail": "input.image is not a PNG data URI", "status": 422})
        pid = next_id()
        with lock:
            state["jobs"][pid] = {"mode": mode, "polls": 0}
        return self.reply(201, self.prediction(pid, "starting"))

    def prediction(self, pid, status, output=None, error=None):
        get = self.base() + "/v1/predictions/" + pid
        return {"id": pid, "status": status, "input": {}, "output": output, "error": error,
                "urls": {"get": get, "cancel": get + "/cancel"}}

    def replicate_get(self, pid):
        job = polled("jobs", pid)
        if not job:
            return self.reply(404, {"detail": "Not found.", "status": 404})
        if job["polls"] < 2:
            return self.reply(200, self.prediction(pid, "processing"))
        if job["mode"] == "failed":
            return self.reply(200, self.prediction(pid, "failed", error="CUDA out of memory"))
        return self.reply(200, self.prediction(pid, "succeeded", output=self.storage(pid + ".mp4")))

    # ---- hostile variants -------------------------------------------------------------------
    def endless(self, head):
        """200 with a body that never ends (no length, then the connection closes): written until
        the client hangs up or the server's lifetime ends."""
        try:
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Connection", "close")
            self.end_headers()
            self.wfile.write(head)
            chunk = b"a" * 65536
            while True:
                self.wfile.write(chunk)
        except (BrokenPipeError, ConnectionResetError):
            pass
        log({"t": time.time(), "host": "api", "method": "closed", "path": self.path, "headers": {}, "body": None})

    def evil_post(self, mode):
        if mode.startswith("echo-key"):
            sent = (self.headers.get("Authorization") or "")[len("Bearer "):]
            echoed = urllib.parse.quote(sent, safe="") if mode == "echo-key-encoded" else sent
            return self.reply(500, {"detail": "x" * 190 + echoed + " is not a key we know"})
        rid = next_id()
        status_url = "file:///etc/passwd" if mode == "status-file" else self.base() + "/evil/%s/status" % mode
        return self.reply(200, {"id": rid, "status": "queued", "status_url": status_url})

    def evil_get(self, mode, tail):
        if tail == "status":
            if mode == "endless-status":
                return self.endless(b'{"status": "')
            if mode == "big-status":
                return self.big_header()
            return self.reply(200, {"status": "done", "video_url": self.base() + "/evil/%s/video" % mode})
        if tail == "video":
            location = {"redirect-file": "file:///etc/passwd",
                        "redirect-dict": "dict://127.0.0.1:%d/info" % state["trap_port"],
                        "redirect-absolute-path": "/evil/%s/video.mp4" % mode,
                        "redirect-relative-path": "video.mp4",
                        "redirect-other-host": "http://localhost:%d/blob/%s.mp4" % (state["storage_port"], next_id()),
                        }.get(mode)
            if location:
                return self.reply(302, b"", "text/plain", headers=[("Location", location)])
            if mode == "endless-video":
                return self.endless(b"")
        if tail in ("video", "video.mp4"):
            with open(args.video, "rb") as f:
                return self.reply(200, f.read(), "video/mp4")
        return self.reply(404, {"error": "not found"})

    def big_header(self):
        """Announces a 100 MiB body, sends a little of it, then closes."""
        try:
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(100 << 20))
            self.send_header("Connection", "close")
            self.end_headers()
            self.wfile.write(b'{"status": "')
        except (BrokenPipeError, ConnectionResetError):
            pass

    # ---- dispatch ---------------------------------------------------------------------------
    def do_POST(self):
        body = self.read_body()
        self.record(body)
        p = self.path
        if p.startswith("/evil/"):
            return self.evil_post(p[len("/evil/"):])
        if p.startswith("/v1beta/models/") and p.endswith(":predictLongRunning"):
            if self.google_key_ok():
                self.veo_submit(p[len("/v1beta/models/"):-len(":predictLongRunning")], body)
            return
        if p.startswith("/fal-ai/"):
            if self.fal_key_ok():
                self.fal_submit(p[len("/fal-ai/"):], body)
            return
        if p.startswith("/v1/models/") and p.endswith("/predictions"):
            if self.replicate_key_ok():
                self.replicate_submit(p.split("/")[4], body)
            return
        self.reply(404, {"error": "not found"})

    def do_GET(self):
        self.record(None)
        p = self.path
        if p.startswith("/evil/"):
            mode, _, tail = p[len("/evil/"):].partition("/")
            return self.evil_get(mode, tail)
        if p.startswith("/v1beta/models/") and "/operations/" in p:
            if self.google_key_ok():
                self.veo_poll(p[len("/v1beta/"):])
            return
        if p.startswith("/v1beta/files/") and ":download" in p:
            if self.google_key_ok():
                fid = p[len("/v1beta/files/"):p.index(":download")]
                self.reply(302, b"", "text/plain", headers=[("Location", self.storage(fid + ".mp4"))])
            return
        if p.startswith("/fal-ai/requests/"):
            if self.fal_key_ok():
                self.fal_get(p[len("/fal-ai/requests/"):])
            return
        if p.startswith("/v1/predictions/"):
            if self.replicate_key_ok():
                self.replicate_get(p[len("/v1/predictions/"):])
            return
        self.reply(404, {"error": "not found"})


class StorageHandler(Handler):
    host_name = "storage"

    def do_GET(self):
        self.record(None)
        # A key must never travel to another origin.
        if self.headers.get("x-goog-api-key") or self.headers.get("Authorization"):
            return self.reply(403, {"error": "an API key was sent to the storage host"})
        if not self.path.startswith("/blob/"):
            return self.reply(404, {"error": "not found"})
        if "-html" in self.path:
            return self.reply(200, b"<html><body>Sign in to continue</body></html>", "text/html")
        with open(args.video, "rb") as f:
            return self.reply(200, f.read(), "video/mp4")

    def do_POST(self):
        self.reply(405, {"error": "read only"})


def serve_trap(sock):
    """A raw TCP port no client of ours may reach: every connection is logged and closed."""
    while True:
        conn, _ = sock.accept()
        conn.settimeout(1)
        try:
            data = conn.recv(200)
        except OSError:
            data = b""
        conn.close()
        log({"t": time.time(), "host": "trap", "method": "", "path": "", "headers": {}, "body": data.decode("latin-1")})


def main():
    global args
    ap = argparse.ArgumentParser()
    ap.add_argument("port_file")
    ap.add_argument("--video", required=True)
    ap.add_argument("--key", required=True)
    ap.add_argument("--lifetime", type=float, default=60)
    ap.add_argument("--log")
    args = ap.parse_args()
    ThreadingHTTPServer.daemon_threads = True
    storage = ThreadingHTTPServer(("127.0.0.1", 0), StorageHandler)
    state["storage_port"] = storage.server_address[1]
    trap = socket.socket()
    trap.bind(("127.0.0.1", 0))
    trap.listen(8)
    state["trap_port"] = trap.getsockname()[1]
    threading.Thread(target=serve_trap, args=(trap,), daemon=True).start()
    api = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    for s in (storage, api):
        threading.Thread(target=s.serve_forever, kwargs={"poll_interval": 0.1}, daemon=True).start()
    with open(args.port_file + ".tmp", "w") as f:
        f.write(str(api.server_address[1]))
    os.replace(args.port_file + ".tmp", args.port_file)
    time.sleep(args.lifetime)
    return 0


if __name__ == "__main__":
    sys.exit(main())
