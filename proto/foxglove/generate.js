// Run with @foxglove/schemas installed (npm install @foxglove/schemas@2.1.0); see SOURCE.md.
// Writes the official Foxglove .proto files for the schemas Touchline needs (and what they import)
// with the generator that ships in @foxglove/schemas, adding only the Java options.
const s = require("@foxglove/schemas/internal");
const fs = require("fs");
const roots = ["Log", "CompressedImage", "RawImage", "ImageAnnotations", "SceneUpdate", "FrameTransforms"];
const want = new Set();
function visit(name) {
  const schema = s.foxgloveMessageSchemas[name];
  if (!schema || schema.protoEquivalent || want.has(name)) return;
  want.add(name);
  for (const f of schema.fields) if (f.type.type === "nested") visit(f.type.schema.name);
}
roots.forEach(visit);
for (const name of want) {
  const schema = s.foxgloveMessageSchemas[name];
  const enums = Object.values(s.foxgloveEnumSchemas).filter((e) => e.parentSchemaName === name);
  let text = s.generateProto(schema, enums);
  text = text.replace("package foxglove;",
    'package foxglove;\n\noption java_package = "touchline.proto.foxglove";\noption java_multiple_files = true;');
  fs.writeFileSync(`out/foxglove/${name}.proto`, text);
}
console.log([...want].sort().join(" "));
