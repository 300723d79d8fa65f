// ROS 2 messages as they travel: ros2msg schemas (a message's definition,
// then each one it uses after a line of '=' and "MSG: pkg/Name") and CDR
// (XCDR1, little or big endian; alignment counted after the 4-byte
// encapsulation header). The same reading as dem.recording in Python.
"use strict";

const CDR_PRIMITIVES = {
  bool: [1, "getUint8"], byte: [1, "getUint8"], char: [1, "getUint8"], uint8: [1, "getUint8"], int8: [1, "getInt8"],
  int16: [2, "getInt16"], uint16: [2, "getUint16"], int32: [4, "getInt32"], uint32: [4, "getUint32"],
  int64: [8, "getBigInt64"], uint64: [8, "getBigUint64"], float32: [4, "getFloat32"], float64: [8, "getFloat64"],
};

function cdrNormalName(name) {
  const parts = name.split("/");
  return `${parts[0]}/${parts[parts.length - 1]}`;
}

// {"pkg/Name": [{name, type, array: null|"sequence"|"fixed", length}]}
function parseRos2msg(name, text) {
  const sections = [[cdrNormalName(name), []]];
  for (const line of text.split("\n")) {
    if (line.startsWith("===")) { sections.push([null, []]); continue; }
    const current = sections[sections.length - 1];
    if (current[0] === null && line.startsWith("MSG:")) { current[0] = cdrNormalName(line.slice(4).trim()); continue; }
    current[1].push(line);
  }
  const definitions = {};
  for (const [full, lines] of sections) {
    const pkg = full.split("/")[0];
    const fields = [];
    for (const raw of lines) {
      const line = raw.split("#")[0].trim();
      if (!line) continue;
      const [typeText, ...rest] = line.split(/\s+/);
      if (rest.join(" ").includes("=")) continue;  // a constant
      let type = typeText, array = null, length = null;
      const bracket = type.match(/^(.*)\[(.*)\]$/);
      if (bracket) {
        type = bracket[1];
        array = bracket[2] && !bracket[2].startsWith("<=") ? "fixed" : "sequence";
        length = array === "fixed" ? Number(bracket[2]) : null;
      }
      if (type.startsWith("string")) type = "string";
      else if (!(type in CDR_PRIMITIVES)) type = cdrNormalName(type.includes("/") ? type : `${pkg}/${type}`);
      fields.push({ name: rest[0], type, array, length });
    }
    definitions[full] = fields;
  }
  return definitions;
}

class CdrDecoder {
  constructor(name, schemaText) {
    this.name = cdrNormalName(name);
    this.definitions = parseRos2msg(name, schemaText);
  }

  decode(bytes) {  // a Uint8Array holding the encapsulation header and the payload
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.little = bytes[1] === 0x01;
    this.offset = 4;
    return this.struct(this.name);
  }

  align(size) { this.offset += (size - ((this.offset - 4) % size)) % size; }

  primitive(type) {
    const [size, getter] = CDR_PRIMITIVES[type];
    this.align(size);
    let value = this.view[getter](this.offset, this.little);
    this.offset += size;
    if (typeof value === "bigint") value = Number(value);
    return type === "bool" ? value !== 0 : value;
  }

  string() {
    const length = this.primitive("uint32");
    const bytes = new Uint8Array(this.view.buffer, this.view.byteOffset + this.offset, Math.max(length - 1, 0));
    this.offset += length;
    return new TextDecoder().decode(bytes);
  }

  value(type) {
    if (type === "string") return this.string();
    if (type in CDR_PRIMITIVES) return this.primitive(type);
    return this.struct(type);
  }

  struct(name) {
    const fields = this.definitions[name];
    if (!fields) throw new Error(`the schema of ${this.name} does not define ${name}`);
    const result = {};
    for (const field of fields) {
      if (field.array === null) { result[field.name] = this.value(field.type); continue; }
      const count = field.array === "fixed" ? field.length : this.primitive("uint32");
      const values = [];
      for (let i = 0; i < count; i++) values.push(this.value(field.type));
      result[field.name] = values;
    }
    return result;
  }
}
