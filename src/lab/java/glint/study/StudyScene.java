package glint.study;

import glint.input.InputException;
import glint.scene.Scene;
import glint.scenefile.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A scene of the speed/accuracy study: its name, file and text (the text keys the reference cache),
 * and optionally an independent reference image (a PFM) rendered at depth 5.
 */
public record StudyScene(String name, Path file, String text, Scene scene, Path independentReference) {

    public static StudyScene load(String name, Path file, Path independentReference) throws IOException, InputException {
        return new StudyScene(name, file, Files.readString(file), SceneLoader.load(file), independentReference);
    }

    public boolean hasIndependentReference() {
        return independentReference != null && Files.isRegularFile(independentReference);
    }
}
