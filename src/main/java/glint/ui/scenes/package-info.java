/**
 * The scene and config files of the window: where they come from ({@link glint.ui.scenes.SceneSource}),
 * read again on F5 and handed over from the watcher ({@link glint.ui.scenes.Reloads}), the scene file
 * watched ({@link glint.ui.scenes.SceneWatcher}), and the folder's other scenes for Page Down and Page Up
 * ({@link glint.ui.scenes.SceneBrowser}). No display needed.
 */
package glint.ui.scenes;
