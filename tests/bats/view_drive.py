#!/usr/bin/env python3
"""Drives a robot through player-view's live page (--drive), as its page
would, on Python's standard library only:

  view_drive.py PORT
      opens /ws, holds "forward" (renewed every 0.2 s, as the page does)
      until the robot has moved 0.2 m, sends "stop" and waits until it
      stands still; drives again and closes the socket without a stop, then
      waits on a new socket until the robot stands still (the tool stopped
      it). All waits share one deadline (30 s); prints what it saw; exit
      status 1 when the robot does not move or does not stop in time.
"""
import json
import math
import os
import socket
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_page  # noqa: E402  (the WebSocket reader)

view_page.DEADLINE = time.monotonic() + 30


def open_socket(port):
    sock = socket.create_connection(("127.0.0.1", port), timeout=10)
    sock.sendall((f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                  "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
    reply = b""
    while b"\r\n\r\n" not in reply:
        reply += view_page.read_exactly(sock, 1)
    if not reply.startswith(b"HTTP/1.1 101"):
        view_page.fail(f"no WebSocket: {reply!r}")
    hello = view_page.next_message(sock)
    if hello.get("type") != "hello" or hello.get("drive") is not True:
        view_page.fail(f"the page may not drive: {hello}")
    return sock


def send_text(sock, text):
    data = text.encode()
    mask = os.urandom(4)
    if len(data) >= 126:
        raise SystemExit("view_drive.py sends short messages only")
    header = bytes([0x81, 0x80 | len(data)])
    sock.sendall(header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data)))


def robot_pose(sock):
    while True:
        message = view_page.next_message(sock)
        if message.get("type") == "frame":
            return [body for body in message["bodies"] if body["filled"]][0]["pose"]


def drive_until_moved(sock, metres):
    """Holds "forward" (renewed every 0.2 s, as the page does) until the
    robot is `metres` from where it was: a wait with the script's deadline,
    however slowly a loaded machine simulates."""
    renewed = 0.0
    first = pose = robot_pose(sock)
    while math.hypot(pose[0] - first[0], pose[1] - first[1]) < metres:
        if time.monotonic() - renewed >= 0.2:
            send_text(sock, json.dumps({"type": "drive", "x": 1, "yaw": 0}))
            renewed = time.monotonic()
        pose = robot_pose(sock)
    return first, pose


def wait_until_still(sock):
    """Until ten frames in a row, over 0.5 s at least, show the same pose:
    the robot stopped (a moving one at 0.3 m/s changes it every frame)."""
    before, since, same = robot_pose(sock), time.monotonic(), 0
    while True:
        pose = robot_pose(sock)
        if pose != before:
            before, since, same = pose, time.monotonic(), 0
            continue
        same += 1
        if same >= 10 and time.monotonic() - since >= 0.5:
            return pose


def main():
    port = int(sys.argv[1])
    sock = open_socket(port)
    first, moved = drive_until_moved(sock, 0.2)
    print(f"drove from {first[:2]} to {moved[:2]}")
    send_text(sock, json.dumps({"type": "stop"}))
    print("stopped at", wait_until_still(sock)[:2])

    drive_until_moved(sock, 0.05)
    sock.close()  # no stop: the tool must stop the robot itself
    watcher = open_socket(port)
    print("stopped after the page closed, at", wait_until_still(watcher)[:2])
    return 0


if __name__ == "__main__":
    sys.exit(main())
