package glint.ui;

import glint.ui.screen.Presenter;
import glint.ui.screen.ShownFrame;
import java.util.ArrayList;
import java.util.List;

/** Keeps every frame the engine presents. */
public final class RecordingPresenter implements Presenter {

    private final List<ShownFrame> frames = new ArrayList<>();
    private String title;

    @Override
    public synchronized void present(ShownFrame frame) {
        frames.add(frame);
    }

    @Override
    public synchronized void title(String newTitle) {
        this.title = newTitle;
    }

    public synchronized List<ShownFrame> frames() {
        return List.copyOf(frames);
    }

    public synchronized ShownFrame last() {
        return frames.isEmpty() ? null : frames.get(frames.size() - 1);
    }

    public synchronized String title() {
        return title;
    }
}
