#!/usr/bin/env python3
"""A client of player-view's live page, on Python's standard library only:

  view_page.py PORT [--map] [--expect-lost]
      fetches http://127.0.0.1:PORT/ and /view.js, opens the WebSocket
      /ws, reads the hello (may the page drive?), the map when --map is
      given, then frames until one
      has laser points (skipping "lost" messages: the tool is reconnecting),
      or with --expect-lost the lost message instead (every wait bounded:
      20 s in all). Prints the map's
      size, the legend's lines and the robot's pose; exit status 1 when
      something is missing.
"""
import base64
import json
import os
import socket
import struct
import sys
import time
import urllib.request

DEADLINE = time.monotonic() + 20


def fail(message):
    print(message)
    sys.exit(1)


def fetch(port, path):
    with urllib.request.urlopen(f"http://127.0.0.1:{port}{path}", timeout=10) as reply:
        return reply.status, reply.headers.get("Content-Type"), reply.read().decode()


def read_exactly(sock, n):
    data = b""
    while len(data) < n:
        sock.settimeout(max(0.1, DEADLINE - time.monotonic()))
        chunk = sock.recv(n - len(data))
        if not chunk:
            fail("the page's WebSocket closed")
        data += chunk
    return data


def next_message(sock):
    """One message, from its frames: a large one (the map) comes in several."""
    payload, opcode = b"", None
    while True:
        first, second = read_exactly(sock, 2)
        size = second & 0x7F
        if size == 126:
            size = struct.unpack(">H", read_exactly(sock, 2))[0]
        elif size == 127:
            size = struct.unpack(">Q", read_exactly(sock, 8))[0]
        payload += read_exactly(sock, size)
        if opcode is None:
            opcode = first & 0x0F
        if first & 0x80:
            break
    if opcode != 1:
        fail(f"not a text message: opcode {opcode}")
    return json.loads(payload)


def main():
    port = int(sys.argv[1])
    status, kind, page = fetch(port, "/")
    if status != 200 or "text/html" not in kind or '<canvas id="view">' not in page:
        fail(f"/ is not the page: {status} {kind}")
    status, kind, script = fetch(port, "/view.js")
    if status != 200 or "javascript" not in kind or "new WebSocket" not in script:
        fail(f"/view.js is not the script: {status} {kind}")

    sock = socket.create_connection(("127.0.0.1", port), timeout=10)
    key = base64.b64encode(os.urandom(16)).decode()
    sock.sendall((f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n"
                  f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
    reply = b""
    while b"\r\n\r\n" not in reply:
        reply += read_exactly(sock, 1)
    if not reply.startswith(b"HTTP/1.1 101"):
        fail(f"no WebSocket: {reply!r}")

    hello = next_message(sock)
    if hello.get("type") != "hello":
        fail(f"the first message is not the hello: {hello.get('type')}")
    print("drive", "allowed" if hello["drive"] else "off")
    if "--map" in sys.argv:
        message = next_message(sock)
        if message.get("type") != "map":
            fail(f"the first message is not the map: {message.get('type')}")
        print(f"map {message['width']}x{message['height']} at {message['resolution']} m")
    if "--expect-lost" in sys.argv:
        message = next_message(sock)
        if message.get("type") != "lost":
            fail(f"not a lost message: {message.get('type')}")
        print("lost:", message["why"])
        return 0
    while time.monotonic() < DEADLINE:
        frame = next_message(sock)
        if frame.get("type") == "lost":
            continue  # the robot's server is not back yet
        if frame.get("type") != "frame":
            fail(f"not a frame: {frame.get('type')}")
        if any(len(dots["points"]) > 100 for dots in frame["dots"]):
            for entry in frame["legend"]:
                print(entry["text"])
            robot = [body for body in frame["bodies"] if body["filled"]][0]
            print("robot", *robot["pose"])
            return 0
    fail("no frame with a laser scan within 20 s")


if __name__ == "__main__":
    sys.exit(main())
