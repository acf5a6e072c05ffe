#include "app/image_file.h"

#include "analysis/io/atomic_file.h"

#include <QBuffer>
#include <QFileInfo>

#include <filesystem>
#include <string_view>

namespace bunraku::app {

analysis::Result<QByteArray> encodeImage(const QImage& image, const QString& file, const QByteArray& format)
{
    QByteArray chosen = format;
    if (chosen.isEmpty()) chosen = QFileInfo(file).suffix().toUpper().toLatin1();
    if (chosen.isEmpty()) chosen = "PNG";
    QByteArray bytes;
    QBuffer buffer(&bytes);
    if (image.isNull() || !buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, chosen.constData()))
        return analysis::makeError(analysis::ErrorCode::Io,
                                   file.toStdString() + ": cannot encode the image as " + chosen.toStdString());
    return bytes;
}

analysis::Status saveImageAtomically(const QImage& image, const QString& file, const QByteArray& format)
{
    auto bytes = encodeImage(image, file, format);
    if (!bytes) return bytes.error();
    return analysis::io::writeFileAtomically(std::filesystem::path(file.toStdString()),
                                             std::string_view(bytes->constData(), std::size_t(bytes->size())));
}

} // namespace bunraku::app
