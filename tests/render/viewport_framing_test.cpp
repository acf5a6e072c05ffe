// The 3D view frames what it shows (render/framing.h, widgets/viewport_camera.cpp): a take of
// another size or place is framed again, Frame All fits everything drawn, Frame Selected one
// part, Reset Camera (Home in the view) the first view; the orbits are drawn over the puppet
// and large enough to see. Pixel assertions on the view's own image.
#include "render_test_support.h"
#include "widgets/viewport_widget.h"

#include <QTest>

#include <algorithm>

using namespace bunraku;

namespace {

/// The view's figures only (no grid or partner): non-background pixels are the figure's.
render::SceneVisibility figuresOnly()
{
    render::SceneVisibility visibility;
    visibility.grid = false;
    visibility.partner = false;
    visibility.axis = false;
    visibility.orbits = false;
    return visibility;
}

render::SceneContent sceneOf(analysis::Take take)
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{std::move(take), {}});
    return scene;
}

/// The puppet (about 1 m tall with its head at 122 cm), still.
analysis::Take puppet() { return test::spreadArmsTake(20); }

/// The same figure at a performer's scale: every sensor position 1.7 times as high and wide.
analysis::Take performer()
{
    analysis::Take take = test::spreadArmsTake(20);
    for (int part = 0; part < 4; ++part)
        for (int axis = 0; axis < 3; ++axis) take.values.col(part * 6 + axis) *= 1.7;
    return take;
}

/// The puppet walking 5 m along +x (across the first view) over its 50 frames.
analysis::Take walker()
{
    analysis::Take take = test::spreadArmsTake(50);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
        for (int part = 0; part < 4; ++part) take.values(f, part * 6) += 500.0 * double(f) / 49.0;
    return take;
}

/// The box of the non-background pixels of `image` (empty when there are none).
QRect figurePixels(const QImage& image)
{
    QRect box;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (!test::isBackground(image.pixel(x, y))) box |= QRect(x, y, 1, 1);
    return box;
}

/// The figure lies wholly inside the image, off its edges, and fills a good part of it.
void requireFramed(const QImage& image, double minimumFill)
{
    const QRect box = figurePixels(image);
    INFO("figure pixels " << box.x() << "," << box.y() << " " << box.width() << "x" << box.height() << " in "
                          << image.width() << "x" << image.height());
    REQUIRE_FALSE(box.isEmpty());
    CHECK(box.left() > 0);
    CHECK(box.top() > 0);
    CHECK(box.right() < image.width() - 1);
    CHECK(box.bottom() < image.height() - 1);
    CHECK(std::max(double(box.width()) / image.width(), double(box.height()) / image.height()) >= minimumFill);
}

struct View {
    widgets::ViewportWidget viewport{nullptr, 0};
    View()
    {
        viewport.resize(400, 300);
        viewport.setVisibility(figuresOnly());
        viewport.show();
        REQUIRE(QTest::qWaitForWindowExposed(&viewport));
    }
    QImage show(analysis::Take take)
    {
        viewport.setScene(sceneOf(std::move(take)));
        viewport.setFrame(0);
        return viewport.grabFramebuffer();
    }
};

} // namespace

TEST_CASE("a 1 m puppet, a 1.7 m performer and a 5 m walk are each framed when shown", "[widgets][viewport][camera]")
{
    View view;
    const QImage small = view.show(puppet());
    requireFramed(small, 0.5);
    const float puppetDistance = view.viewport.camera().distance;
    REQUIRE_FALSE(view.viewport.cameraChosen());

    const render::Bounds puppetBounds = view.viewport.framedBounds();
    const QImage tall = view.show(performer());
    requireFramed(tall, 0.5);
    // A larger figure: the camera moved back, and the figure fills the view about as much as
    // the puppet did.
    CHECK(view.viewport.framedBounds().extent() / puppetBounds.extent() > 1.3f);
    CHECK(view.viewport.camera().distance / puppetDistance > 1.2f);
    CHECK(figurePixels(tall).height() == Approx(figurePixels(small).height()).epsilon(0.2));

    // The walk: the whole path is in view, at its first and at its last frame.
    view.show(walker());
    for (int frame : {0, 49}) {
        view.viewport.setFrame(frame);
        const QImage image = view.viewport.grabFramebuffer();
        INFO("frame " << frame);
        requireFramed(image, 0.1);
    }
    const QRect first = (view.viewport.setFrame(0), figurePixels(view.viewport.grabFramebuffer()));
    const QRect last = (view.viewport.setFrame(49), figurePixels(view.viewport.grabFramebuffer()));
    CHECK(std::abs(first.center().x() - last.center().x()) > 150); // it walked across the view
}

TEST_CASE("a moved camera keeps its angle: reframed for a take of another size, kept for one of the same", "[widgets][viewport][camera]")
{
    View view;
    view.show(puppet());
    render::Camera moved = view.viewport.camera();
    moved.angleDeg = 200.0f;
    moved.elevationDeg = 40.0f;
    moved.distance *= 0.5f; // zoomed in on the figure
    view.viewport.setCamera(moved);
    REQUIRE(view.viewport.cameraChosen());

    // Another take of the same size and place (a recomputed take): the camera stays.
    analysis::Take same = puppet();
    same.values.col(2).array() += 3.0; // the head 3 cm higher
    view.show(same);
    CHECK(view.viewport.camera().distance == Approx(moved.distance));
    CHECK(view.viewport.camera().angleDeg == Approx(200.0f));

    // A take of another size: refitted, from the same angle and elevation.
    const QImage image = view.show(performer());
    CHECK(view.viewport.camera().angleDeg == Approx(200.0f));
    CHECK(view.viewport.camera().elevationDeg == Approx(40.0f));
    CHECK(view.viewport.camera().distance > moved.distance * 2.0f);
    requireFramed(image, 0.45);
}

TEST_CASE("Frame All, Frame Selected and Reset Camera (Home in the view) fit the scene", "[widgets][viewport][camera]")
{
    View view;
    view.show(puppet());
    const render::Camera first = view.viewport.camera();
    REQUIRE(first.angleDeg == Approx(340.0f));
    REQUIRE(first.elevationDeg == Approx(15.0f));

    // Lost: looking far away, too close.
    render::Camera lost = first;
    lost.angleDeg = 90.0f;
    lost.target = {500.0f, -300.0f, 0.0f};
    lost.distance = 15.0f;
    view.viewport.setCamera(lost);
    CHECK(figurePixels(view.viewport.grabFramebuffer()).isEmpty());

    view.viewport.frameAll();
    CHECK(view.viewport.camera().angleDeg == Approx(90.0f)); // the view's direction kept
    requireFramed(view.viewport.grabFramebuffer(), 0.6);
    // Every corner of what is drawn projects inside the view.
    const QSize pixels(view.viewport.width(), view.viewport.height());
    const render::Bounds bounds = view.viewport.renderer()->displayedBounds(view.viewport.camera());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point((corner & 1) ? bounds.upper.x : bounds.lower.x, (corner & 2) ? bounds.upper.y : bounds.lower.y,
                              (corner & 4) ? bounds.upper.z : bounds.lower.z);
        const QPointF pixel = view.viewport.camera().project(point, pixels).pixel;
        CHECK(QRectF(0, 0, pixels.width(), pixels.height()).contains(pixel));
    }

    // Frame Selected (the right hand, as clicked): closer than the whole figure, the hand in the
    // middle of the view.
    const float allDistance = view.viewport.camera().distance;
    view.viewport.frameSelected(QStringLiteral("right_hand"));
    CHECK(view.viewport.camera().distance < 0.6f * allDistance);
    const auto hand = view.viewport.renderer()->displayedSensorPositions(0, 0, view.viewport.camera())[3];
    const QPointF handPixel = view.viewport.camera().project(hand, pixels).pixel;
    CHECK(QRectF(100, 75, 200, 150).contains(handPixel)); // near the middle of the 400 x 300 view

    // Home with the view focused: the first view again.
    view.viewport.setFocus();
    QTest::keyClick(&view.viewport, Qt::Key_Home);
    CHECK(view.viewport.camera().angleDeg == Approx(first.angleDeg));
    CHECK(view.viewport.camera().elevationDeg == Approx(first.elevationDeg));
    CHECK(view.viewport.camera().distance == Approx(first.distance));
    CHECK_FALSE(view.viewport.cameraChosen());
}

TEST_CASE("orbits are drawn over the puppet with a ball several pixels wide at each sensor", "[widgets][viewport][orbits]")
{
    View view;
    view.show(test::spreadArmsTake(20));
    const QImage without = view.viewport.grabFramebuffer();
    render::SceneVisibility visibility = figuresOnly();
    visibility.orbits = true;
    visibility.orbitVisibility = render::OrbitVisibility::Always;
    view.viewport.setVisibility(visibility);
    const QImage with = view.viewport.grabFramebuffer();
    const QSize pixels(view.viewport.width(), view.viewport.height());
    const auto sensors = view.viewport.renderer()->displayedSensorPositions(0, 0, view.viewport.camera());
    REQUIRE(sensors.size() == 4);
    for (std::size_t k = 0; k < sensors.size(); ++k) {
        // Each sensor lies inside its part; its ball covers the part around it: every pixel
        // within 2 pixels of the sensor changed.
        const QPoint centre = view.viewport.camera().project(sensors[k], pixels).pixel.toPoint();
        int changed = 0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) changed += with.pixel(centre + QPoint(dx, dy)) != without.pixel(centre + QPoint(dx, dy));
        INFO("sensor " << k);
        CHECK(changed == 25);
    }
}
