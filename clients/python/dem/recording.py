"""Recordings of a server's telemetry (``demctl record FILE.mcap``) read back:
MCAP files (https://mcap.dev/spec) whose channels carry ROS 2 messages -
ros2msg schemas, CDR payloads - decoded with nothing but the schemas the
file holds, so any such file (a ROS 2 bag in MCAP) reads the same way.

    from dem.recording import Recording
    with Recording("out/press.mcap") as recording:
        print(recording.topics())   # {"/dem/press/plate_forces": "dem_interfaces/msg/PlateForces", ...}
        for message in recording.messages("/dem/press/plate_forces"):
            top = next(w for w in message.data.walls if w.name == "top")
            print(message.log_time, message.data.cycle, top.normal_stress, top.settlement)

Messages decode to objects with the schema's field names as attributes
(``types.SimpleNamespace``): numbers as int and float, strings as str,
``uint8[]`` as bytes, other arrays as lists. Times are nanoseconds since
the Unix epoch. Compressed chunks (zstd, lz4) are not read: ``demctl
record`` writes uncompressed ones.
"""

import collections
import pathlib
import struct
import types
import zlib

MAGIC = b"\x89MCAP0\r\n"
_HEADER, _FOOTER, _SCHEMA, _CHANNEL, _MESSAGE, _CHUNK = 0x01, 0x02, 0x03, 0x04, 0x05, 0x06

Message = collections.namedtuple("Message", "topic schema log_time publish_time data")
Message.__doc__ = "A message of a recording: its topic, schema name, times (ns) and decoded data."


class RecordingError(ValueError):
    """The file is not an MCAP recording this module can read; the message says where and why."""


class _Bytes:
    """Little-endian reads over bytes, naming the file in every error."""

    def __init__(self, data, where):
        self.data, self.offset, self.where = data, 0, where

    def take(self, size):
        if self.offset + size > len(self.data):
            raise RecordingError(f"{self.where}: truncated at byte {self.offset} (needs {size} more)")
        chunk = self.data[self.offset:self.offset + size]
        self.offset += size
        return chunk

    def unpack(self, fmt):
        return struct.unpack("<" + fmt, self.take(struct.calcsize("<" + fmt)))

    def string(self):
        (length,) = self.unpack("I")
        return self.take(length).decode()

    def prefixed(self):
        (length,) = self.unpack("I")
        return self.take(length)

    def done(self):
        return self.offset >= len(self.data)


class Recording:
    """An MCAP file's schemas, channels and messages (read at once: recordings are small)."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        data = self.path.read_bytes()
        if not data.startswith(MAGIC):
            raise RecordingError(f"{self.path}: not an MCAP file (it does not start with MCAP's magic bytes)")
        self.profile = ""
        self.schemas = {}   # id -> (name, encoding, text)
        self.channels = {}  # id -> (topic, schema id, message encoding)
        self._messages = []  # (channel id, log time, publish time, bytes)
        self._records(_Bytes(data[len(MAGIC):], str(self.path)), top_level=True)
        self._decoders = {}

    def _records(self, reader, top_level):
        while not reader.done():
            opcode, length = reader.unpack("BQ")
            body = _Bytes(reader.take(length), reader.where)
            if opcode == _HEADER:
                self.profile = body.string()
            elif opcode == _SCHEMA:
                (schema_id,) = body.unpack("H")
                name, encoding = body.string(), body.string()
                self.schemas[schema_id] = (name, encoding, body.prefixed().decode())
            elif opcode == _CHANNEL:
                channel_id, schema_id = body.unpack("HH")
                topic, encoding = body.string(), body.string()
                self.channels[channel_id] = (topic, schema_id, encoding)
            elif opcode == _MESSAGE:
                channel_id, _, log_time, publish_time = body.unpack("HIQQ")
                self._messages.append((channel_id, log_time, publish_time, body.data[body.offset:]))
            elif opcode == _CHUNK and top_level:
                _, _, size, crc = body.unpack("QQQI")
                compression = body.string()
                (records_length,) = body.unpack("Q")
                records = body.take(records_length)
                if compression:
                    raise RecordingError(f"{self.path}: a chunk is compressed with {compression}, which this reader "
                                         "does not read (demctl record writes uncompressed chunks)")
                if crc and zlib.crc32(records) != crc:
                    raise RecordingError(f"{self.path}: a chunk's CRC does not match its records (a damaged file)")
                self._records(_Bytes(records, reader.where), top_level=False)
            elif opcode == _FOOTER:
                return  # the trailing magic follows
            # Message indexes, chunk indexes, statistics, summary offsets,
            # data end: what an indexed reader needs, nothing a full read does.

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def topics(self):
        """Topic -> schema name of every channel."""
        return {topic: self.schemas[schema][0] if schema in self.schemas else ""
                for topic, schema, _ in self.channels.values()}

    def messages(self, topic=None):
        """The messages (of one topic, or all) in the order they were recorded, decoded."""
        for channel_id, log_time, publish_time, data in self._messages:
            channel_topic, schema_id, encoding = self.channels[channel_id]
            if topic is not None and channel_topic != topic:
                continue
            name, schema_encoding, text = self.schemas[schema_id]
            if (encoding, schema_encoding) != ("cdr", "ros2msg"):
                raise RecordingError(f"{self.path}: {channel_topic} holds {encoding} messages of a {schema_encoding} "
                                     "schema; this reader decodes cdr messages of ros2msg schemas")
            if schema_id not in self._decoders:
                self._decoders[schema_id] = CdrDecoder(name, text)
            yield Message(channel_topic, name, log_time, publish_time, self._decoders[schema_id].decode(data))

    def raw_messages(self, topic=None):
        """(topic, log time, publish time, CDR bytes) of each message, undecoded."""
        for channel_id, log_time, publish_time, data in self._messages:
            channel_topic = self.channels[channel_id][0]
            if topic is None or channel_topic == topic:
                yield channel_topic, log_time, publish_time, data

    def __len__(self):
        return len(self._messages)


# --- ros2msg schemas -------------------------------------------------------

_PRIMITIVES = {  # name -> (struct format, size)
    "bool": ("?", 1), "byte": ("B", 1), "char": ("B", 1), "uint8": ("B", 1), "int8": ("b", 1),
    "int16": ("h", 2), "uint16": ("H", 2), "int32": ("i", 4), "uint32": ("I", 4),
    "int64": ("q", 8), "uint64": ("Q", 8), "float32": ("f", 4), "float64": ("d", 8),
}
Field = collections.namedtuple("Field", "name type array length")  # array: None, "sequence" or "fixed"


def parse_schema(name, text):
    """A ros2msg schema (the message's definition, then each one it uses
    after a line of '=' and "MSG: <package>/<Name>") as {full name: [Field]}."""
    definitions = {}
    current, lines = name, []
    for line in text.splitlines() + ["=" * 3]:
        if line.startswith("==="):
            definitions[_normal(current)] = lines
            current, lines = None, []
        elif current is None and line.startswith("MSG:"):
            current = line[4:].strip()
        else:
            lines.append(line)
    parsed = {}
    for full, body in definitions.items():
        package = full.split("/")[0]
        fields = []
        for line in body:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            type_text, rest = line.split(None, 1)
            if "=" in rest:
                continue  # a constant: NAME=value
            field_name = rest.split()[0]  # a default value may follow
            array, length = None, None
            if type_text.endswith("]"):
                type_text, bound = type_text[:-1].split("[")
                array = "fixed" if bound and not bound.startswith("<=") else "sequence"
                length = int(bound) if array == "fixed" else None
            if type_text.startswith("string<=") or type_text.startswith("wstring"):
                type_text = "string"
            if type_text not in _PRIMITIVES and type_text != "string":
                type_text = _normal(type_text if "/" in type_text else f"{package}/{type_text}")
            fields.append(Field(field_name, type_text, array, length))
        parsed[_normal(full)] = fields
    return parsed


def _normal(name):
    """"pkg/msg/Name" and "pkg/Name" alike."""
    parts = name.split("/")
    return f"{parts[0]}/{parts[-1]}"


class CdrDecoder:
    """Decodes CDR (XCDR1, as ROS 2 and Cyclone DDS write it) by a ros2msg schema."""

    def __init__(self, name, schema_text):
        self.name = _normal(name)
        self.definitions = parse_schema(name, schema_text)
        if self.name not in self.definitions:
            raise RecordingError(f"the schema of {name} does not define it")

    def decode(self, data):
        if len(data) < 4:
            raise RecordingError(f"a {self.name} message of {len(data)} bytes has no CDR header")
        if data[1] not in (0x00, 0x01):
            raise RecordingError(f"a {self.name} message is not plain CDR (representation {data[0]:#x}{data[1]:02x})")
        little = data[1] == 0x01
        self._order = "<" if little else ">"
        self._data, self._offset = data, 4  # alignment counts from after the 4-byte header
        return self._struct(self.name)

    def _align(self, size):
        self._offset += (-(self._offset - 4)) % size

    def _primitive(self, type_name):
        fmt, size = _PRIMITIVES[type_name]
        self._align(size)
        (value,) = struct.unpack_from(self._order + fmt, self._data, self._offset)
        self._offset += size
        return value

    def _string(self):
        length = self._primitive("uint32")
        text = self._data[self._offset:self._offset + max(length - 1, 0)].decode()
        self._offset += length
        return text

    def _value(self, type_name):
        if type_name == "string":
            return self._string()
        if type_name in _PRIMITIVES:
            return self._primitive(type_name)
        return self._struct(type_name)

    def _struct(self, name):
        if name not in self.definitions:
            raise RecordingError(f"the schema of {self.name} does not define {name}")
        values = {}
        for field in self.definitions[name]:
            if field.array is None:
                values[field.name] = self._value(field.type)
                continue
            count = field.length if field.array == "fixed" else self._primitive("uint32")
            if field.type in ("uint8", "byte", "char"):
                values[field.name] = bytes(self._data[self._offset:self._offset + count])
                self._offset += count
            else:
                values[field.name] = [self._value(field.type) for _ in range(count)]
        return types.SimpleNamespace(**values)


def read(path, topic=None):
    """Every message of a recording (or of one topic), decoded, as a list."""
    return list(Recording(path).messages(topic))
