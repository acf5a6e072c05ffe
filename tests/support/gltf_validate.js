// Validates a glTF file with the Khronos glTF validator (npm `gltf-validator`) and prints its
// report as JSON on standard output: node gltf_validate.js FILE (tests/support/gltf_validator.h).
const fs = require("fs");
const path = require("path");
const validator = require("gltf-validator");

const file = process.argv[2];
const bytes = new Uint8Array(fs.readFileSync(file));
validator
    .validateBytes(bytes, { uri: path.basename(file), maxIssues: 200 })
    .then((report) => process.stdout.write(JSON.stringify(report)))
    .catch((error) => {
        console.error(String(error));
        process.exit(1);
    });
