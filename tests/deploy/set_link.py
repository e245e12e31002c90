"""Sets the network interface that holds ADDRESS down or up, in the network namespace this runs in.

cut_link.sh runs it in a helper container that shares the network namespace of the container
whose link is cut (docker run --network container:ID --cap-add NET_ADMIN). A link set down keeps
its address, as a pulled cable does; a container taken off its network and put back would get
whatever address Docker hands out then, while its peers keep sending to the one Fast DDS announced.
The runtime image has python3 (fastdds-tools needs it) and no iproute2, hence the ioctls.

Usage: python3 set_link.py ADDRESS up|down
"""
import fcntl
import socket
import struct
import sys

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


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in ("up", "down"):
        sys.exit("usage: set_link.py ADDRESS up|down")
    address, state = sys.argv[1], sys.argv[2]
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    names = [name for _, name in socket.if_nameindex() if ipv4_address(sock, name) == address]
    if len(names) != 1:
        sys.exit(f"set_link.py: {len(names)} interfaces hold {address} here, expected one")
    name = names[0]
    flags = struct.unpack("H", request(sock, SIOCGIFFLAGS, name)[:2])[0]
    flags = flags | IFF_UP if state == "up" else flags & ~IFF_UP
    request(sock, SIOCSIFFLAGS, name, struct.pack("H", flags))
    print(f"set_link.py: {name} ({address}) {state}")


main()
