#pragma once
/// Images written by the workbench (screenshots, exported frames): encoded in memory, then
/// written with the atomic, durable helper (analysis/io/atomic_file.h).

#include "analysis/core/result.h"

#include <QByteArray>
#include <QImage>
#include <QString>

namespace bunraku::app {

/// The image encoded as `format` ("PNG", "JPG"...; empty: by the file name's suffix, PNG when
/// there is none); an Io error naming `file` when it cannot be encoded.
analysis::Result<QByteArray> encodeImage(const QImage& image, const QString& file, const QByteArray& format = {});

/// encodeImage, then writeFileAtomically: the file holds the old image or the new one.
analysis::Status saveImageAtomically(const QImage& image, const QString& file, const QByteArray& format = {});

} // namespace bunraku::app
