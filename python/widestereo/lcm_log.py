"""LCM log files (lcm-logger's format) read and written without LCM's Python
binding (Debian has none). Each event is a 28-byte header, big-endian:

    sync word 0xEDA1DA01, event number (int64), utime (int64),
    channel length (int32), data length (int32)

then the channel name and the data (an encoded message: its 8-byte type
fingerprint first). Every size is checked against the file before use.
"""
import collections
import os
import struct

_SYNC = 0xEDA1DA01
_HEADER = struct.Struct(">IqqII")
_MAX_CHANNEL = 1000  # LCM's own reader accepts channel names up to 999 bytes

Event = collections.namedtuple("Event", "number utime channel message")


def _classes_by_fingerprint():
    from . import MESSAGE_TYPES
    return {cls._get_packed_fingerprint(): cls for cls in MESSAGE_TYPES.values()}


def decode(data):
    """The message of encoded data, as its widestereo class; ValueError when
    its fingerprint is none of widestereo's types or it does not decode."""
    cls = _classes_by_fingerprint().get(bytes(data[:8]))
    if cls is None:
        raise ValueError("not a widestereo message (unknown type fingerprint %s)" % bytes(data[:8]).hex())
    try:
        return cls.decode(bytes(data))
    except (ValueError, struct.error) as error:
        raise ValueError("%s does not decode: %s" % (cls.__name__, error)) from None


def read_log(path, channels=None, raw=False):
    """Yields the events of an LCM log as Event(number, utime, channel,
    message): message decoded (a widestereo class; the bytes for another
    type's) or, with raw=True, the bytes. channels: a set of names to keep.
    Raises ValueError naming the byte where the file stops being a log."""
    size = os.path.getsize(path)
    with open(path, "rb") as f:
        offset = 0
        while offset < size:
            header = f.read(_HEADER.size)
            if len(header) < _HEADER.size:
                raise ValueError("%s: byte %d: a truncated event header" % (path, offset))
            sync, number, utime, channel_length, data_length = _HEADER.unpack(header)
            if sync != _SYNC:
                raise ValueError("%s: byte %d: no sync word (not an LCM log, or damaged)" % (path, offset))
            end = offset + _HEADER.size + channel_length + data_length
            if not 0 < channel_length < _MAX_CHANNEL or end > size:
                raise ValueError("%s: byte %d: event %d's sizes (channel %d, data %d bytes) exceed "
                                 "the file" % (path, offset, number, channel_length, data_length))
            channel = f.read(channel_length).decode("utf-8", "replace")
            data = f.read(data_length)
            offset = end
            if channels is not None and channel not in channels:
                continue
            message = data
            if not raw and data[:8] in _classes_by_fingerprint():
                message = decode(data)
            yield Event(number, utime, channel, message)


def write_log(path, events):
    """Writes (channel, message, utime) tuples as an LCM log: message a
    widestereo class instance (encoded here) or bytes already encoded."""
    with open(path, "wb") as f:
        for number, (channel, message, utime) in enumerate(events):
            data = message if isinstance(message, (bytes, bytearray)) else message.encode()
            name = channel.encode("utf-8")
            if not 0 < len(name) < _MAX_CHANNEL:
                raise ValueError("channel name of %d bytes (1 to %d)" % (len(name), _MAX_CHANNEL - 1))
            f.write(_HEADER.pack(_SYNC, number, int(utime), len(name), len(data)))
            f.write(name)
            f.write(data)
