"""Watches the loopback interface for RTPS packets and counts those that
carry a word in clear text (dds_security.sh: with DDS Security's discovery,
liveliness and RTPS protection on, no topic name may show).

    rtps_sniff.py SECONDS WORD   prints "packets N" and "clear M"; exit 2
                                 when packets cannot be captured (not root)
"""
import socket
import sys
import time


def main():
    seconds, word = float(sys.argv[1]), sys.argv[2].encode()
    try:
        capture = socket.socket(socket.AF_PACKET, socket.SOCK_RAW, socket.ntohs(0x0003))  # every protocol
        capture.bind(("lo", 0))
    except (PermissionError, OSError) as error:
        print(f"cannot capture on lo: {error}")
        return 2
    capture.settimeout(0.2)
    end = time.monotonic() + seconds
    packets = clear = 0
    while time.monotonic() < end:
        try:
            data = capture.recv(65535)
        except socket.timeout:
            continue
        if b"RTPS" not in data:
            continue
        packets += 1
        if word in data:
            clear += 1
            if clear == 1:
                at = data.index(word)
                print("first seen in:", data[max(0, at - 48):at + 64])
    print(f"packets {packets}")
    print(f"clear {clear}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
