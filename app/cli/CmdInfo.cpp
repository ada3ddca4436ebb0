// rigidlab-cli info: what the core makes of a scene file, as text or as one JSON object.
#include "Cli.h"
#include "io/SceneImport.h"
#include "scene/BodyProperties.h"

#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace rl::cli {

namespace {

QJsonArray toJson(const Vec3& v) {
    return QJsonArray{v.x, v.y, v.z};
}

QJsonArray toJson(const Mat3& m) {
    // Row-major rows, so the JSON reads like the matrix (glm stores columns).
    QJsonArray rows;
    for (int r = 0; r < 3; ++r)
        rows.append(QJsonArray{m[0][r], m[1][r], m[2][r]});
    return rows;
}

QString formatVec(const Vec3& v) {
    return QString("(%1, %2, %3)").arg(v.x, 0, 'g', 9).arg(v.y, 0, 'g', 9).arg(v.z, 0, 'g', 9);
}

} // namespace

int runInfo(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription("Print the bodies of a scene with their derived physical properties.");
    parser.addHelpOption();
    parser.addPositionalArgument("scene", "Scene file (.rlscene, .obj or any format assimp reads).");
    parser.addOption({"json", "Print one JSON object instead of text."});
    if (const std::optional<int> done = parseArguments(parser, arguments, "info"))
        return *done;
    if (parser.positionalArguments().size() != 1) {
        printError(QStringLiteral("rigidlab-cli info: expected exactly one scene file (see --help)"));
        return kExitUsage;
    }
    const std::string path = parser.positionalArguments().constFirst().toStdString();
    Result<Scene> scene = importScene(path);
    if (!scene) {
        printError(scene.error().toString());
        return kExitFailure;
    }

    QJsonArray bodies;
    QString text;
    int anchors = 0;
    double totalMass = 0.0;
    for (size_t i = 0; i < scene->bodies.size(); ++i) {
        const BodyDef& body = scene->bodies[i];
        Result<BodyProperties> props = computeBodyProperties(*scene, body);
        if (!props) {
            Error e = props.error();
            e.file = path;
            printError(e.toString());
            return kExitFailure;
        }
        anchors += body.anchor ? 1 : 0;
        if (!body.anchor)
            totalMass += props->mass;
        QJsonArray warnings;
        for (const std::string& w : props->warnings)
            warnings.append(QString::fromStdString(w));
        QJsonObject b{{"index", static_cast<int>(i)},
                      {"name", QString::fromStdString(body.name)},
                      {"anchor", body.anchor},
                      {"material", QString::fromStdString(body.material)},
                      {"volume", props->volume},
                      {"mass", props->mass},
                      {"com", toJson(props->com)},
                      {"vertex_mean", toJson(props->vertexMean)},
                      {"inertia", toJson(props->inertia)},
                      {"principal_inertia", toJson(props->principalMoments)},
                      {"hull_vertices", props->hullVertexCount},
                      {"flat", props->flat},
                      {"concave", props->concave},
                      {"warnings", warnings}};
        bodies.append(b);
        text += QString("%1  %2%3\n").arg(i, 4).arg(QString::fromStdString(body.name), body.anchor ? "  [anchor]" : "");
        text += QString("      material %1, volume %2 m^3, mass %3 kg, hull vertices %4\n")
                    .arg(QString::fromStdString(body.material))
                    .arg(props->volume, 0, 'g', 9)
                    .arg(props->mass, 0, 'g', 9)
                    .arg(props->hullVertexCount);
        text += QString("      centre of mass %1, principal inertia %2\n")
                    .arg(formatVec(props->com), formatVec(props->principalMoments));
        for (const std::string& w : props->warnings)
            text += QString("      warning: %1\n").arg(QString::fromStdString(w));
    }

    QJsonArray materials;
    for (const MaterialDef& m : scene->materials)
        materials.append(QJsonObject{{"name", QString::fromStdString(m.name)},
                                     {"density", m.density},
                                     {"friction", m.friction},
                                     {"restitution", m.restitution}});
    if (parser.isSet("json")) {
        QJsonObject root{{"file", QString::fromStdString(path)},
                         {"body_count", bodies.size()},
                         {"anchor_count", anchors},
                         {"dynamic_mass", totalMass},
                         {"materials", materials},
                         {"bodies", bodies}};
        printOut(QString::fromUtf8(QJsonDocument(root).toJson(QJsonDocument::Indented)));
    } else {
        printOut(QString("%1: %2 bodies (%3 anchors, %4 dynamic), dynamic mass %5 kg\n")
                     .arg(QString::fromStdString(path))
                     .arg(bodies.size())
                     .arg(anchors)
                     .arg(bodies.size() - anchors)
                     .arg(totalMass, 0, 'g', 9) +
                 text);
    }
    return kExitOk;
}

} // namespace rl::cli
