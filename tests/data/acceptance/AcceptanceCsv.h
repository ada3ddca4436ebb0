// Helpers of tests/app/tst_acceptance*.cpp: bake a scene with the built rigidlab-cli at default settings and read
// the CSV back the way a reviewer does (DESIGN.md §5), plus the OBJ vertices needed to find a body's lowest point.
#pragma once

#include "app/CliRunner.h"

#include <QCryptographicHash>
#include <QFile>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QtGlobal>

#include <array>
#include <cmath>
#include <vector>

namespace rl::test::acceptance {

inline QString dataPath(const QString& name) {
    return QStringLiteral(RL_TEST_DATA_DIR "/acceptance/") + name;
}

// One row of the CSV: x y z qw qx qy qz vx vy vz wx wy wz.
using Row = std::array<double, 13>;
enum Col { X, Y, Z, QW, QX, QY, QZ, VX, VY, VZ, WX, WY, WZ };

struct Csv {
    bool ok = false;
    QString error;
    int frames = 0; // rows per body, frame 0 included
    int bodies = 0;
    QStringList names;
    std::vector<bool> anchor;
    std::vector<Row> rows; // frame-major

    const Row& at(int frame, int body) const { return rows[static_cast<size_t>(frame) * bodies + body]; }
    int last() const { return frames - 1; }
    int byName(const QString& name) const { return static_cast<int>(names.indexOf(name)); }
    bool allFinite() const {
        for (const Row& r : rows)
            for (double v : r)
                if (!std::isfinite(v))
                    return false;
        return true;
    }
    // The dynamic body whose centre starts highest.
    int topBody() const {
        int top = -1;
        for (int b = 0; b < bodies; ++b)
            if (!anchor[b] && (top < 0 || at(0, b)[Y] > at(0, top)[Y]))
                top = b;
        return top;
    }
    double horizontalDrift(int body) const {
        return std::hypot(at(last(), body)[X] - at(0, body)[X], at(last(), body)[Z] - at(0, body)[Z]);
    }
    // Largest speed of any dynamic body in the last second, by finite differences of the positions.
    double maxSpeedLastSecond(double fps = 60.0) const {
        double worst = 0.0;
        for (int f = std::max(1, frames - static_cast<int>(fps)); f < frames; ++f)
            for (int b = 0; b < bodies; ++b) {
                if (anchor[b])
                    continue;
                const Row &a = at(f - 1, b), &c = at(f, b);
                worst = std::max(worst, std::sqrt((c[X] - a[X]) * (c[X] - a[X]) + (c[Y] - a[Y]) * (c[Y] - a[Y]) +
                                                  (c[Z] - a[Z]) * (c[Z] - a[Z])) *
                                            fps);
            }
        return worst;
    }
    // Largest displacement of any dynamic body between frame 0 and the last frame.
    double maxDisplacement() const {
        double worst = 0.0;
        for (int b = 0; b < bodies; ++b) {
            if (anchor[b])
                continue;
            const Row &a = at(0, b), &c = at(last(), b);
            worst = std::max(worst, std::sqrt((c[X] - a[X]) * (c[X] - a[X]) + (c[Y] - a[Y]) * (c[Y] - a[Y]) +
                                              (c[Z] - a[Z]) * (c[Z] - a[Z])));
        }
        return worst;
    }
};

// Splits one CSV line, RFC 4180 quotes allowed.
inline QStringList splitCsvLine(const QString& line) {
    QStringList out;
    QString cur;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cur += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                cur += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out << cur;
            cur.clear();
        } else {
            cur += c;
        }
    }
    out << cur;
    return out;
}

inline Csv readCsv(const QString& path) {
    Csv csv;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        csv.error = QStringLiteral("cannot open ") + path;
        return csv;
    }
    const QByteArray header = f.readLine().trimmed();
    if (header != "frame,time,body,name,anchor,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz") {
        csv.error = QStringLiteral("unexpected header: ") + QString::fromUtf8(header);
        return csv;
    }
    int lastFrame = -1;
    while (!f.atEnd()) {
        const QString line = QString::fromUtf8(f.readLine()).trimmed();
        if (line.isEmpty())
            continue;
        const QStringList cells = splitCsvLine(line);
        if (cells.size() != 18) {
            csv.error = QStringLiteral("bad row: ") + line;
            return csv;
        }
        const int frame = cells[0].toInt(), body = cells[2].toInt();
        if (frame == 0) {
            if (body != csv.bodies) {
                csv.error = QStringLiteral("bodies out of order in frame 0");
                return csv;
            }
            csv.names << cells[3];
            csv.anchor.push_back(cells[4] == QLatin1String("1"));
            ++csv.bodies;
        }
        if (frame != lastFrame && frame != lastFrame + 1) {
            csv.error = QStringLiteral("frames out of order at ") + line;
            return csv;
        }
        lastFrame = frame;
        Row r{};
        for (int k = 0; k < 13; ++k) {
            bool ok = false;
            const double v = cells[5 + k].toDouble(&ok);
            r[k] = ok ? v : std::nan(""); // "nan", "inf" or garbage: not finite either way
        }
        csv.rows.push_back(r);
    }
    csv.frames = lastFrame + 1;
    if (csv.bodies == 0 || csv.rows.size() != static_cast<size_t>(csv.frames) * csv.bodies) {
        csv.error = QStringLiteral("row count is not frames x bodies");
        return csv;
    }
    csv.ok = true;
    return csv;
}

struct Bake {
    CliRun run;
    Csv csv;
    QByteArray csvHash, bakeHash;
    QString command;
};

// `rigidlab-cli bake SCENE --seconds 10 --csv OUT.csv -o OUT.bake [extra]` in a temporary folder.
inline Bake bake(const QString& scene, const QStringList& extra = {}, bool keepCsv = true,
                 const QString& seconds = QStringLiteral("10")) {
    QTemporaryDir dir;
    const QString csvPath = dir.filePath("out.csv"), bakePath = dir.filePath("out.bake");
    QStringList args{"bake", scene, "--seconds", seconds, "--csv", csvPath, "-o", bakePath, "--quiet"};
    args << extra;
    Bake b;
    b.command = QStringLiteral("rigidlab-cli ") + args.join(' ');
    b.run = runCli(args);
    auto hash = [](const QString& path) {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return QByteArray();
        QCryptographicHash h(QCryptographicHash::Sha256);
        h.addData(&f);
        return h.result().toHex();
    };
    b.csvHash = hash(csvPath);
    b.bakeHash = hash(bakePath);
    if (keepCsv)
        b.csv = readCsv(csvPath);
    return b;
}

// Vertices of every `o` object of an OBJ file, in file order and file coordinates. Blender 3.4's new exporter
// (wm.obj_export) can write the same name for several objects ("o Cube" for Cube, Cube.001, ...), so objects are
// matched to bodies by their place in the file (bodies are in file order, anchors included).
struct ObjObject {
    QString name;
    std::vector<std::array<double, 3>> vertices;
};

inline std::vector<ObjObject> objObjects(const QString& path) {
    std::vector<ObjObject> out;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return out;
    while (!f.atEnd()) {
        const QByteArray line = f.readLine().trimmed();
        if (line.startsWith("o "))
            out.push_back({QString::fromUtf8(line.mid(2).trimmed()), {}});
        else if (line.startsWith("v ") && !out.empty()) {
            const QList<QByteArray> p = line.simplified().split(' ');
            if (p.size() >= 4)
                out.back().vertices.push_back({p[1].toDouble(), p[2].toDouble(), p[3].toDouble()});
        }
    }
    return out;
}

// Lowest world y any vertex of any dynamic body reaches in the run: each vertex is carried from frame 0 by the
// body's rotation since frame 0 about its centre of mass (DESIGN.md §5). Returns NaN when the OBJ's objects do not
// match the CSV's bodies one to one.
inline double lowestVertexY(const Csv& csv, const QString& objPath, int* atFrame = nullptr, QString* body = nullptr) {
    const std::vector<ObjObject> objects = objObjects(objPath);
    if (static_cast<int>(objects.size()) != csv.bodies)
        return std::nan("");
    double lowest = 1e300;
    for (int b = 0; b < csv.bodies; ++b) {
        if (objects[b].name != csv.names[b])
            return std::nan("");
        if (csv.anchor[b])
            continue;
        const Row& r0 = csv.at(0, b);
        for (int f = 0; f < csv.frames; ++f) {
            const Row& r = csv.at(f, b);
            const double w = r[QW], x = r[QX], y = r[QY], z = r[QZ];
            for (const auto& v : objects[b].vertices) {
                const double px = v[0] - r0[X], py = v[1] - r0[Y], pz = v[2] - r0[Z];
                // y component of q p q*
                const double tx = 2 * (y * pz - z * py), tz = 2 * (x * py - y * px);
                const double ty = 2 * (z * px - x * pz);
                const double wy = py + w * ty + (z * tx - x * tz) + r[Y];
                if (wy < lowest) {
                    lowest = wy;
                    if (atFrame)
                        *atFrame = f;
                    if (body)
                        *body = QString::number(b) + " " + csv.names[b];
                }
            }
        }
    }
    return lowest;
}

} // namespace rl::test::acceptance
