package glint.ui.scenes;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/** The scene files (.yaml, .yml) of a scene's folder, by name: where Page Down and Page Up go. */
final class SceneFolder {

    /** The scene to open, its number in the folder from 1, and how many there are; or null and why not. */
    record Neighbour(Path path, int number, int of, String problem) {
    }

    private SceneFolder() {
    }

    /**
     * The next (+1) or previous (-1) scene file of {@code current}'s folder, round to the first or last,
     * written beside {@code current} as it is written; without a path when there is no other or the folder
     * cannot be listed.
     */
    static Neighbour neighbour(Path current, int step) {
        Path at = current.toAbsolutePath().normalize();
        List<Path> scenes;
        try (Stream<Path> files = Files.list(at.getParent())) {
            scenes = files.filter(f -> {
                String name = f.getFileName().toString().toLowerCase(Locale.ROOT);
                return (name.endsWith(".yaml") || name.endsWith(".yml")) && Files.isRegularFile(f);
            }).map(f -> f.toAbsolutePath().normalize()).sorted().toList();
        } catch (IOException | RuntimeException e) {
            return new Neighbour(null, 0, 0, "cannot list " + at.getParent() + ": " + e.getMessage());
        }
        int i = scenes.indexOf(at);
        if (scenes.isEmpty() || i >= 0 && scenes.size() == 1) {
            return new Neighbour(null, 0, 0, "no other scene in " + at.getParent());
        }
        int next = i < 0 ? (step > 0 ? 0 : scenes.size() - 1) : Math.floorMod(i + step, scenes.size());
        return new Neighbour(current.resolveSibling(scenes.get(next).getFileName()), next + 1, scenes.size(), "");
    }
}
