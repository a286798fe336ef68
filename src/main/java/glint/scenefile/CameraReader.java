package glint.scenefile;

import glint.input.InputException;
import glint.math.Vector3d;
import glint.scene.Camera;
import glint.scene.View;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.snakeyaml.engine.v2.nodes.Node;

/** The cameras of a scene file: its {@code camera} and its named {@code views}. */
final class CameraReader {

    private static final Set<String> CAMERA_KEYS = new LinkedHashSet<>(List.of("position", "look_at", "up", "fov", "aperture",
            "focus"));
    private static final Set<String> VIEW_KEYS = new LinkedHashSet<>(List.of("name", "position", "look_at", "up", "fov",
            "aperture", "focus"));

    private final YamlTree yaml;

    CameraReader(YamlTree yaml) {
        this.yaml = yaml;
    }

    /** {@code views:} a list of camera mappings, each with an optional name; at most {@link SceneLoader#MAX_VIEWS}. */
    List<View> views(Node node) throws InputException {
        List<View> views = new ArrayList<>();
        ViewNames names = new ViewNames();
        for (Node item : yaml.sequence(node, "views")) {
            if (views.size() == SceneLoader.MAX_VIEWS) {
                throw yaml.error(item, "too many views: at most " + SceneLoader.MAX_VIEWS + " (keys 1 to 9 go to them)");
            }
            String what = names.nextDefault();
            Map<String, Node> m = yaml.mapping(item, what, VIEW_KEYS);
            boolean written = m.containsKey("name");
            String name = written ? yaml.string(m.get("name"), what) : what;
            String problem = written ? names.problemWithWritten(name) : names.problemWithDefault();
            if (problem != null) {
                throw yaml.error(written ? m.get("name") : item, problem);
            }
            names.add(name, written);
            views.add(new View(name, camera(item, m)));
        }
        return views;
    }

    Camera camera(Node node) throws InputException {
        return camera(node, yaml.mapping(node, "camera", CAMERA_KEYS));
    }

    /** A camera from the entries {@code m} of the mapping {@code node} (a scene's camera or a view). */
    private Camera camera(Node node, Map<String, Node> m) throws InputException {
        Vector3d position = m.containsKey("position") ? yaml.vector(m.get("position"), "position")
                : new Vector3d(0, 1, -5);
        Vector3d lookAt = m.containsKey("look_at") ? yaml.vector(m.get("look_at"), "look_at")
                : position.add(Vector3d.UNIT_Z);
        Vector3d up = m.containsKey("up") ? yaml.vector(m.get("up"), "up") : Vector3d.UNIT_Y;
        double fov = m.containsKey("fov") ? yaml.number(m.get("fov"), "fov") : Camera.DEFAULT_FOV;
        if (!(fov > 0 && fov < 180)) {
            throw yaml.error(m.get("fov"), "fov must lie strictly between 0 and 180 degrees, got "
                    + YamlTree.source(m.get("fov"), fov));
        }
        Vector3d view = lookAt.sub(position);
        if (lookAt.equals(position)) {
            throw yaml.error(m.getOrDefault("look_at", node), "look_at must differ from the camera position");
        }
        double distance = view.isFinite() ? view.length() : Double.POSITIVE_INFINITY;
        if (!(distance <= SceneLoader.LONGEST && distance >= SceneLoader.SHORTEST)) {
            throw yaml.error(m.getOrDefault("look_at", node), "look_at is " + distance(position, lookAt)
                    + " from the camera position; it must be between 1e-150 and 1e150 away");
        }
        Vector3d upChecked = SceneLoader.lengthSafe(up);
        if (upChecked.length() == 0
                || upChecked.cross(view).length() <= 1e-12 * upChecked.length() * view.length()) {
            throw yaml.error(m.getOrDefault("up", node),
                    "up must not be zero or parallel to the viewing direction (look_at - position)");
        }
        Camera camera = Camera.lookAt(position, lookAt, upChecked, fov);
        double aperture = m.containsKey("aperture") ? aperture(m.get("aperture")) : 0;
        double focus = m.containsKey("focus") ? focus(m.get("focus"))
                : m.containsKey("look_at") ? camera.focus() : Camera.DEFAULT_FOCUS;
        return camera.withLens(aperture, focus);
    }

    /** {@code aperture}: the lens radius, from 0 (a pinhole) to the longest length a scene has. */
    private double aperture(Node node) throws InputException {
        double aperture = yaml.number(node, "aperture");
        if (aperture < 0) {
            throw yaml.error(node, "aperture must be >= 0, got " + YamlTree.source(node, aperture));
        }
        if (aperture > SceneLoader.LONGEST) {
            throw yaml.error(node, "aperture must be at most 1e150, got " + YamlTree.source(node, aperture));
        }
        return aperture + 0.0; // -0 is 0
    }

    /** {@code focus}: the distance of the plane in focus, a length as a radius is. */
    private double focus(Node node) throws InputException {
        double focus = yaml.number(node, "focus");
        if (!(focus > 0)) {
            throw yaml.error(node, "focus must be > 0, got " + YamlTree.source(node, focus));
        }
        if (!(focus >= SceneLoader.SHORTEST && focus <= SceneLoader.LONGEST)) {
            throw yaml.error(node, "focus must lie between 1e-150 and 1e150 (its square must be a"
                    + " normal double), got " + YamlTree.source(node, focus));
        }
        return focus;
    }

    /** The distance between two points for a message, without overflow: "3.0e+160". */
    private static String distance(Vector3d a, Vector3d b) {
        double dx = a.x() / 2 - b.x() / 2, dy = a.y() / 2 - b.y() / 2, dz = a.z() / 2 - b.z() / 2;
        double largest = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
        double length = 2 * largest * Math.sqrt((dx / largest) * (dx / largest) + (dy / largest) * (dy / largest)
                + (dz / largest) * (dz / largest));
        return InputException.beyond(length, length > 1 ? SceneLoader.LONGEST : SceneLoader.SHORTEST, 2);
    }
}
