"""Sets the network interface that holds ADDRESS down or up, in the network namespace this runs in.

cut_link.sh runs it in a helper container that shares the network namespace of the container
whose link is cut (docker run --network container:ID --cap-add NET_ADMIN). A link set down keeps
its address, as a pulled cable does; a container taken off its network and put back would get
whatever address Docker hands out then, while its peers keep sending to the one Fast DDS announced.
The runtime image has python3 (fastdds-tools needs it) and no iproute2, hence the ioctls.

Usage: python3 set_link.py ADDRESS up|down
       python3 set_link.py ADDRESS down SECONDS   # down, then up again SECONDS later

The second form is one helper container for the whole cut: its length is then SECONDS, not
SECONDS plus a second container's start-up (several seconds on a loaded machine).
"""
import fcntl
import socket
import struct
import sys
import time

SIOCGIFFLAGS, SIOCSIFFLAGS, SIOCGIFADDR = 0x8913, 0x8914, 0x8915
IFF_UP = 0x1


def request(sock, code, name, payload=b""):
    ifreq = struct.pack("16s16s", name.encode(), payload)
    return fcntl.ioctl(sock, code, ifreq)[16:]


def ipv4_address(sock, name):
    try:
        sockaddr = request(sock, SIOCGIFADDR, name)
    except OSError:
        return None  # no IPv4 address on it
    return socket.inet_ntoa(sockaddr[4:8])


def set_state(sock, name, address, state):
    flags = struct.unpack("H", request(sock, SIOCGIFFLAGS, name)[:2])[0]
    flags = flags | IFF_UP if state == "up" else flags & ~IFF_UP
    request(sock, SIOCSIFFLAGS, name, struct.pack("H", flags))
    print(f"set_link.py: {name} ({address}) {state}", flush=True)


def main():
    args = sys.argv[1:]
    ok = len(args) == 2 and args[1] in ("up", "down")
    ok = ok or (len(args) == 3 and args[1] == "down" and args[2].isdigit())
    if not ok:
        sys.exit("usage: set_link.py ADDRESS up|down [SECONDS]")
    address, state = args[0], args[1]
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    names = [name for _, name in socket.if_nameindex() if ipv4_address(sock, name) == address]
    if len(names) != 1:
        sys.exit(f"set_link.py: {len(names)} interfaces hold {address} here, expected one")
    set_state(sock, names[0], address, state)
    if len(args) == 3:
        time.sleep(int(args[2]))
        set_state(sock, names[0], address, "up")


main()
