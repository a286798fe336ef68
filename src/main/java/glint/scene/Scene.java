package glint.scene;

import glint.math.Vector3d;
import java.util.List;

/** An immutable scene as loaded from a file; {@code views} are the cameras it lists besides its own. */
public record Scene(Camera camera, Vector3d background, Vector3d ambient,
                    List<Light> lights, List<SceneObject> objects, List<View> views) {

    public Scene {
        lights = List.copyOf(lights);
        objects = List.copyOf(objects);
        views = List.copyOf(views);
    }

    /** A scene without views. */
    public Scene(Camera camera, Vector3d background, Vector3d ambient, List<Light> lights,
                 List<SceneObject> objects) {
        this(camera, background, ambient, lights, objects, List.of());
    }

    public Scene withCamera(Camera newCamera) {
        return new Scene(newCamera, background, ambient, lights, objects, views);
    }
}
