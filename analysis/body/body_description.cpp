#include "analysis/body/body_description.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

namespace bunraku::analysis {

namespace {

using nlohmann::json;

/// Reports the first problem met while walking the document, with its JSON path.
class Walker {
public:
    explicit Walker(std::string source) : m_source(std::move(source)) {}

    Error fail(const std::string& path, const std::string& what) const
    {
        return parseError(m_source, 0, (path.empty() ? std::string("document") : path) + ": " + what);
    }

    std::optional<Error> positiveNumber(const json& object, const std::string& path, const char* key, double& out) const
    {
        if (!object.contains(key)) return fail(path, std::string("missing \"") + key + "\" (a positive number)");
        const json& value = object.at(key);
        if (!value.is_number()) return fail(path + "." + key, "expected a positive number");
        out = value.get<double>();
        if (!std::isfinite(out) || out <= 0.0) return fail(path + "." + key, "expected a positive number, got " + value.dump());
        return std::nullopt;
    }

    std::optional<Error> vector3(const json& object, const std::string& path, const char* key, Eigen::Vector3d& out,
                                 bool positive) const
    {
        const json& value = object.at(key);
        const std::string here = path + "." + key;
        const char* expected = positive ? "expected an array of 3 positive numbers" : "expected an array of 3 numbers";
        if (!value.is_array() || value.size() != 3) return fail(here, expected);
        for (int i = 0; i < 3; ++i) {
            if (!value[std::size_t(i)].is_number()) return fail(here, expected);
            out[i] = value[std::size_t(i)].get<double>();
            if (!std::isfinite(out[i]) || (positive && out[i] <= 0.0)) return fail(here, std::string(expected) + ", got " + value.dump());
        }
        return std::nullopt;
    }

    std::optional<Error> colour(const json& object, const std::string& path, Eigen::Vector3d& out) const
    {
        if (!object.contains("colour")) return std::nullopt;
        const json& value = object.at("colour");
        const std::string here = path + ".colour";
        if (value.is_string()) {
            const std::string text = value.get<std::string>();
            if (text.size() != 7 || text[0] != '#') return fail(here, "expected \"#rrggbb\", got " + value.dump());
            for (int i = 0; i < 3; ++i) {
                unsigned int channel = 0;
                std::istringstream stream(text.substr(std::size_t(1 + 2 * i), 2));
                stream >> std::hex >> channel;
                if (stream.fail() || !stream.eof()) return fail(here, "expected \"#rrggbb\", got " + value.dump());
                out[i] = double(channel) / 255.0;
            }
            return std::nullopt;
        }
        if (auto error = vector3(object, path, "colour", out, false)) return fail(here, "expected \"#rrggbb\" or [r, g, b] in 0..1");
        if (out.minCoeff() < 0.0 || out.maxCoeff() > 1.0) return fail(here, "expected [r, g, b] in 0..1");
        return std::nullopt;
    }

    std::optional<Error> primitive(const json& object, const std::string& path, const BodyPart& part, Primitive& out) const
    {
        if (!object.is_object()) return fail(path, "expected an object");
        if (!object.contains("shape") || !object.at("shape").is_string())
            return fail(path, "missing \"shape\" (one of box, cylinder, ellipsoid, frustum)");
        out.name = object.value("name", std::string());
        const std::string shape = object.at("shape").get<std::string>();
        if (shape == "box") {
            out.shape = PrimitiveShape::Box;
            if (!object.contains("size")) return fail(path, "a box needs \"size\": [x, y, z] edge lengths in cm");
            if (auto e = vector3(object, path, "size", out.size, true)) return e;
        } else if (shape == "ellipsoid") {
            out.shape = PrimitiveShape::Ellipsoid;
            if (!object.contains("radii")) return fail(path, "an ellipsoid needs \"radii\": [x, y, z] in cm");
            if (auto e = vector3(object, path, "radii", out.size, true)) return e;
        } else if (shape == "cylinder") {
            out.shape = PrimitiveShape::Cylinder;
            if (auto e = positiveNumber(object, path, "radius", out.radius)) return e;
            if (auto e = positiveNumber(object, path, "length", out.length)) return e;
        } else if (shape == "frustum") {
            out.shape = PrimitiveShape::Frustum;
            if (auto e = positiveNumber(object, path, "radius", out.radius)) return e;
            if (auto e = positiveNumber(object, path, "top_radius", out.topRadius)) return e;
            if (auto e = positiveNumber(object, path, "length", out.length)) return e;
        } else {
            return fail(path + ".shape", "expected one of box, cylinder, ellipsoid, frustum, got \"" + shape + "\"");
        }
        Eigen::Vector3d position = Eigen::Vector3d::Zero();
        Eigen::Vector3d angles = Eigen::Vector3d::Zero();
        if (object.contains("position"))
            if (auto e = vector3(object, path, "position", position, false)) return e;
        if (object.contains("yaw_pitch_roll_deg"))
            if (auto e = vector3(object, path, "yaw_pitch_roll_deg", angles, false)) return e;
        out.part_T_primitive.translation = position;
        out.part_T_primitive.rotation = rotationFromYawPitchRoll(YawPitchRoll{angles[0], angles[1], angles[2]});
        out.density = part.density;
        if (object.contains("density"))
            if (auto e = positiveNumber(object, path, "density", out.density)) return e;
        out.colour = part.colour;
        if (auto e = colour(object, path, out.colour)) return e;
        return std::nullopt;
    }

private:
    std::string m_source;
};

/// The source's primitives reflected in the part's y axis (see body_description.h).
std::vector<Primitive> reflectedPrimitives(const std::vector<Primitive>& source)
{
    const Eigen::Matrix3d flip = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
    std::vector<Primitive> reflected = source;
    for (Primitive& primitive : reflected) {
        primitive.part_T_primitive.translation.y() = -primitive.part_T_primitive.translation.y();
        const Eigen::Matrix3d rotation = flip * primitive.part_T_primitive.rotation.toRotationMatrix() * flip;
        primitive.part_T_primitive.rotation = Eigen::Quaterniond(rotation).normalized();
    }
    return reflected;
}

} // namespace

std::string_view primitiveShapeName(PrimitiveShape shape)
{
    switch (shape) {
    case PrimitiveShape::Box: return "box";
    case PrimitiveShape::Cylinder: return "cylinder";
    case PrimitiveShape::Ellipsoid: return "ellipsoid";
    case PrimitiveShape::Frustum: return "frustum";
    }
    return "box";
}

double Primitive::volume() const
{
    constexpr double pi = std::numbers::pi;
    switch (shape) {
    case PrimitiveShape::Box: return size.prod();
    case PrimitiveShape::Cylinder: return pi * radius * radius * length;
    case PrimitiveShape::Ellipsoid: return 4.0 / 3.0 * pi * size.prod();
    case PrimitiveShape::Frustum: return pi * length / 3.0 * (radius * radius + radius * topRadius + topRadius * topRadius);
    }
    return 0.0;
}

bool Primitive::containsLocal(const Eigen::Vector3d& p) const
{
    switch (shape) {
    case PrimitiveShape::Box: return (p.cwiseAbs().array() <= 0.5 * size.array()).all();
    case PrimitiveShape::Cylinder: return std::abs(p.z()) <= 0.5 * length && p.head<2>().squaredNorm() <= radius * radius;
    case PrimitiveShape::Ellipsoid: return p.cwiseQuotient(size).squaredNorm() <= 1.0;
    case PrimitiveShape::Frustum: {
        if (std::abs(p.z()) > 0.5 * length) return false;
        const double along = (p.z() + 0.5 * length) / length;
        const double r = radius + (topRadius - radius) * along;
        return p.head<2>().squaredNorm() <= r * r;
    }
    }
    return false;
}

Eigen::Vector3d Primitive::halfExtents() const
{
    switch (shape) {
    case PrimitiveShape::Box: return 0.5 * size;
    case PrimitiveShape::Ellipsoid: return size;
    case PrimitiveShape::Cylinder: return {radius, radius, 0.5 * length};
    case PrimitiveShape::Frustum: {
        const double r = std::max(radius, topRadius);
        return {r, r, 0.5 * length};
    }
    }
    return Eigen::Vector3d::Zero();
}

double BodyPart::mass() const
{
    double total = 0.0;
    for (const Primitive& primitive : primitives) total += primitive.mass();
    return total;
}

int BodyDescription::partIndex(std::string_view partName) const
{
    for (std::size_t i = 0; i < parts.size(); ++i)
        if (parts[i].name == partName) return int(i);
    return -1;
}

double BodyDescription::mass() const
{
    double total = 0.0;
    for (const BodyPart& part : parts) total += part.mass();
    return total;
}

Result<BodyDescription> parseBodyDescription(std::string_view jsonText, std::string_view sourceName)
{
    const std::string source(sourceName);
    const Walker walk(source);
    auto parsed = io::parseJsonText(jsonText, source, "not valid JSON");
    if (!parsed) return parsed.error();
    const json document = std::move(parsed).value();
    if (!document.is_object()) return walk.fail("", "expected a JSON object with \"parts\"");
    BodyDescription body;
    body.source = source;
    body.name = document.value("name", source);
    body.mirrorFramePart = "shoulder";
    if (document.contains("mirror_frame_part")) {
        if (!document.at("mirror_frame_part").is_string()) return walk.fail("mirror_frame_part", "expected a take part name");
        body.mirrorFramePart = document.at("mirror_frame_part").get<std::string>();
    }
    if (!document.contains("parts") || !document.at("parts").is_array() || document.at("parts").empty())
        return walk.fail("parts", "expected a non-empty array of parts");

    const json& parts = document.at("parts");
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const json& object = parts[i];
        const std::string path = "parts[" + std::to_string(i) + "]";
        if (!object.is_object()) return walk.fail(path, "expected an object");
        BodyPart part;
        if (!object.contains("name") || !object.at("name").is_string() || object.at("name").get<std::string>().empty())
            return walk.fail(path, "missing \"name\" (a non-empty string)");
        part.name = object.at("name").get<std::string>();
        if (body.partIndex(part.name) >= 0) return walk.fail(path + ".name", "duplicate part name \"" + part.name + "\"");
        if (!object.contains("driven_by") || !object.at("driven_by").is_string())
            return walk.fail(path, "missing \"driven_by\" (the take part that poses it, e.g. \"arm\")");
        part.drivenBy = object.at("driven_by").get<std::string>();
        if (object.contains("mirror_of")) {
            if (!object.at("mirror_of").is_string()) return walk.fail(path + ".mirror_of", "expected a part name");
            part.mirrorOf = object.at("mirror_of").get<std::string>();
            const int source_index = body.partIndex(part.mirrorOf);
            if (source_index < 0)
                return walk.fail(path + ".mirror_of", "expected the name of an earlier part, got \"" + part.mirrorOf + "\"");
            const BodyPart& mirrored_source = body.parts[std::size_t(source_index)];
            if (mirrored_source.mirrored)
                return walk.fail(path + ".mirror_of", "\"" + part.mirrorOf + "\" is itself mirrored");
            if (mirrored_source.drivenBy != part.drivenBy)
                return walk.fail(path + ".driven_by", "a mirrored part is driven by its source's take part \"" +
                                                          mirrored_source.drivenBy + "\"");
            if (object.contains("primitives"))
                return walk.fail(path + ".primitives", "a mirrored part takes its source's primitives; remove them");
            part.mirrored = true;
            part.density = mirrored_source.density;
            part.colour = mirrored_source.colour;
            part.primitives = reflectedPrimitives(mirrored_source.primitives);
            body.parts.push_back(std::move(part));
            continue;
        }
        if (auto e = walk.positiveNumber(object, path, "density", part.density)) return *e;
        if (auto e = walk.colour(object, path, part.colour)) return *e;
        if (!object.contains("primitives") || !object.at("primitives").is_array() || object.at("primitives").empty())
            return walk.fail(path + ".primitives", "expected a non-empty array of primitives");
        const json& primitives = object.at("primitives");
        for (std::size_t k = 0; k < primitives.size(); ++k) {
            Primitive primitive;
            if (auto e = walk.primitive(primitives[k], path + ".primitives[" + std::to_string(k) + "]", part, primitive)) return *e;
            part.primitives.push_back(std::move(primitive));
        }
        body.parts.push_back(std::move(part));
    }
    return body;
}

Result<BodyDescription> loadBodyDescription(const std::filesystem::path& path)
{
    auto text = io::readTextFile(path, io::kDocumentLimitBytes);
    if (!text) return text.error();
    return parseBodyDescription(*text, path.string());
}

} // namespace bunraku::analysis
