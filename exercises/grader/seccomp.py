"""The system calls a submission's sandbox refuses: a seccomp filter that bubblewrap
installs (``bwrap --seccomp FD``) before it starts the kernel.

A notebook needs none of them, and each would let something pass between
submissions or widen what a submission can reach:

* the kernel's key store (``add_key``, ``request_key``, ``keyctl``): a user's
  keyring outlives its processes, so a key one submission adds could be read by
  the next one graded as the same sandbox user;
* namespaces (``unshare``, ``setns``, and ``clone`` with a namespace flag): a new
  user namespace gives uid 0 and mounts inside it, attack surface a grader
  does not need; ``clone3``, whose flags a filter cannot read, answers "not
  implemented", so the C library falls back to ``clone``;
* mounts (``mount``, ``umount2``, ``pivot_root``, ``chroot`` and the new mount
  API).

They fail with ``EPERM``; so does every system call of another architecture's
calling convention (32-bit calls from a 64-bit process, x32).

The filter is classic BPF, written here for x86-64 and AArch64 (little-endian);
on another machine :func:`program` returns None and the sandbox runs without it
(``check_sandbox`` then says so in the tests).
"""

import errno
import os
import platform
import struct
import sys

# seccomp return values and BPF opcodes (linux/seccomp.h, linux/filter.h)
RET_ALLOW = 0x7FFF0000
RET_ERRNO = 0x00050000
LD_W_ABS = 0x20  # BPF_LD | BPF_W | BPF_ABS
JEQ_K = 0x15  # BPF_JMP | BPF_JEQ | BPF_K
JGE_K = 0x35  # BPF_JMP | BPF_JGE | BPF_K
JSET_K = 0x45  # BPF_JMP | BPF_JSET | BPF_K
RET_K = 0x06  # BPF_RET | BPF_K
# offsets in struct seccomp_data: nr, arch, args[0] (its low 32 bits, little-endian)
NR, ARCH, ARG0_LOW = 0, 4, 16
#: clone flags that make a namespace (CLONE_NEWNS, CGROUP, UTS, IPC, USER, PID, NET)
NAMESPACE_FLAGS = 0x00020000 | 0x02000000 | 0x04000000 | 0x08000000 | 0x10000000
NAMESPACE_FLAGS |= 0x20000000 | 0x40000000
#: x32 system calls on x86-64 carry this bit
X32_BIT = 0x40000000

REFUSED = (
    "add_key",
    "request_key",
    "keyctl",
    "unshare",
    "setns",
    "mount",
    "umount2",
    "pivot_root",
    "chroot",
    "open_tree",
    "move_mount",
    "fsopen",
    "fsconfig",
    "fsmount",
    "fspick",
    "mount_setattr",
)

#: machine -> (AUDIT_ARCH, system call numbers)
ARCHES = {
    "x86_64": (
        0xC000003E,
        {
            "add_key": 248,
            "request_key": 249,
            "keyctl": 250,
            "unshare": 272,
            "setns": 308,
            "mount": 165,
            "umount2": 166,
            "pivot_root": 155,
            "chroot": 161,
            "open_tree": 428,
            "move_mount": 429,
            "fsopen": 430,
            "fsconfig": 431,
            "fsmount": 432,
            "fspick": 433,
            "mount_setattr": 442,
            "clone": 56,
            "clone3": 435,
        },
    ),
    "aarch64": (
        0xC00000B7,
        {
            "add_key": 217,
            "request_key": 218,
            "keyctl": 219,
            "unshare": 97,
            "setns": 268,
            "mount": 40,
            "umount2": 39,
            "pivot_root": 41,
            "chroot": 51,
            "open_tree": 428,
            "move_mount": 429,
            "fsopen": 430,
            "fsconfig": 431,
            "fsmount": 432,
            "fspick": 433,
            "mount_setattr": 442,
            "clone": 220,
            "clone3": 435,
        },
    ),
}
ARCHES["arm64"] = ARCHES["aarch64"]
ARCHES["amd64"] = ARCHES["x86_64"]


def _assemble(code):
    """Bytes of a program given as (opcode, jump-if-true, jump-if-false, k) with
    jumps to labels (strings) or None; a bare string in the list is a label."""
    where, k = {}, 0
    for item in code:
        if isinstance(item, str):
            where[item] = k
        else:
            k += 1
    out, k = [], 0
    for item in code:
        if isinstance(item, str):
            continue
        op, jt, jf, value = item
        jt = where[jt] - k - 1 if isinstance(jt, str) else 0
        jf = where[jf] - k - 1 if isinstance(jf, str) else 0
        out.append(struct.pack("<HBBI", op, jt, jf, value))
        k += 1
    return b"".join(out)


def program(machine=None):
    """The filter for this machine as bytes (``bwrap --seccomp`` reads them), or
    None on a machine it is not written for."""
    machine = (machine or platform.machine()).lower()
    if machine not in ARCHES or sys.byteorder != "little":
        return None
    arch, numbers = ARCHES[machine]
    code = [
        (LD_W_ABS, None, None, ARCH),
        (JEQ_K, "native", None, arch),
        (RET_K, None, None, RET_ERRNO | errno.EPERM),  # another calling convention
        "native",
        (LD_W_ABS, None, None, NR),
    ]
    if machine in ("x86_64", "amd64"):
        code.append((JGE_K, "deny", None, X32_BIT))
    code += [(JEQ_K, "deny", None, numbers[name]) for name in REFUSED]
    code += [
        (JEQ_K, "enosys", None, numbers["clone3"]),
        (JEQ_K, "clone", None, numbers["clone"]),
        (RET_K, None, None, RET_ALLOW),
        "clone",
        (LD_W_ABS, None, None, ARG0_LOW),
        (JSET_K, "deny", None, NAMESPACE_FLAGS),
        (RET_K, None, None, RET_ALLOW),
        "deny",
        (RET_K, None, None, RET_ERRNO | errno.EPERM),
        "enosys",
        (RET_K, None, None, RET_ERRNO | errno.ENOSYS),
    ]
    return _assemble(code)


def filter_fd(data):
    """A file descriptor holding ``data`` from its start (a memory file), for one
    ``bwrap --seccomp`` to read; the caller passes it to bwrap and closes it."""
    fd = os.memfd_create("accelab-seccomp", 0)  # not inherited unless passed
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]
    os.lseek(fd, 0, os.SEEK_SET)
    return fd
