package glint.scene;

import glint.math.Vector3d;
import java.util.List;

/** An immutable scene as loaded from a file. */
public record Scene(Camera camera, Vector3d background, Vector3d ambient,
                    List<Light> lights, List<SceneObject> objects) {

    public Scene {
        lights = List.copyOf(lights);
        objects = List.copyOf(objects);
    }

    public Scene withCamera(Camera newCamera) {
        return new Scene(newCamera, background, ambient, lights, objects);
    }
}
