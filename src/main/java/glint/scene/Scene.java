package glint.scene;

import glint.math.Vector3d;
import java.util.List;

/**
 * An immutable scene as loaded from a file; {@code views} are the cameras it lists besides its own,
 * {@code render} how it is meant to be seen (its {@code render:} block).
 */
public record Scene(Camera camera, Vector3d background, Vector3d ambient,
                    List<Light> lights, List<SceneObject> objects, List<View> views, RenderBlock render) {

    public Scene {
        lights = List.copyOf(lights);
        objects = List.copyOf(objects);
        views = List.copyOf(views);
        render = render == null ? RenderBlock.NONE : render;
    }

    /** A scene without a render block. */
    public Scene(Camera camera, Vector3d background, Vector3d ambient, List<Light> lights,
                 List<SceneObject> objects, List<View> views) {
        this(camera, background, ambient, lights, objects, views, RenderBlock.NONE);
    }

    /** A scene without views. */
    public Scene(Camera camera, Vector3d background, Vector3d ambient, List<Light> lights,
                 List<SceneObject> objects) {
        this(camera, background, ambient, lights, objects, List.of());
    }

    public Scene withCamera(Camera newCamera) {
        return new Scene(newCamera, background, ambient, lights, objects, views, render);
    }
}
