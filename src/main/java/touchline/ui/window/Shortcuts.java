package touchline.ui.window;

import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.MenuItem;

import java.util.ArrayList;
import java.util.List;

/**
 * Every keyboard shortcut of the window, for the shortcut sheet and the views' help: the
 * menus' accelerators and mnemonics read from the menu bar itself (so the sheet cannot drift
 * from what the keys do), plus the keys the views answer to inside themselves.
 */
final class Shortcuts {

    /** One key and what it does; {@code viewId} is empty for the window's own keys. */
    record Key(String viewId, String keys, String what) {
        String line() {
            return String.format("  %-22s %s", keys, what);
        }
    }

    /** The keys views handle themselves (no menu item shows them); the referee's from its own list. */
    static final List<Key> VIEW_KEYS = viewKeys();

    private static List<Key> viewKeys() {
        List<Key> keys = new ArrayList<>(List.of(
            new Key("options", "Space", "switch the selected option on or off"),
            new Key("options", "Enter", "open the selected option's visualisation"),
            new Key("options", "type in the filter", "show only the options whose name matches"),
            new Key("debug-console", "Ctrl+F", "search (matches are highlighted)"),
            new Key("debug-console", "Ctrl+C", "copy the selected lines (all shown lines when none is selected)"),
            new Key("network", "Up / Down", "walk the datagrams; the selected one stays in view while more arrive"),
            new Key("field-plot", "Ctrl+F", "find a field path: type to filter, Up/Down choose, Enter adds it"),
            new Key("gamecontroller", "Ctrl+Z", "undo the last action"),            new Key("nao", "W A S D Q E", "walk and turn while the walk pad has the keyboard"),
            new Key("", "Tab / Shift+Tab", "move the keyboard to the next / previous control (the focused one is ringed)"),
            new Key("", "Esc", "close a help window, quick-open or a dialog"),
            new Key("", "F10 or Alt", "the menu bar; the underlined letter opens a menu")));
        int at = keys.indexOf(keys.stream().filter(k -> k.viewId().equals("gamecontroller")).findFirst().orElseThrow());
        for (touchline.ui.referee.RefereeKey k : touchline.ui.referee.RefereeKey.values()) {
            keys.add(at++, new Key("gamecontroller", k.keys(), k.what() + " (HSL; not while typing in a field)"));
        }
        return List.copyOf(keys);
    }

    private final List<Key> menuKeys;

    Shortcuts(MenuBar bar) {
        List<Key> keys = new ArrayList<>();
        for (Menu m : bar.getMenus()) {
            String menu = plain(m.getText());
            String mnemonic = mnemonic(m.getText());
            if (!mnemonic.isEmpty()) {
                keys.add(new Key("", "Alt+" + mnemonic, "the " + menu + " menu"));
            }
            collect(m, menu, keys);
        }
        this.menuKeys = List.copyOf(keys);
    }

    private static void collect(Menu menu, String path, List<Key> out) {
        for (MenuItem item : menu.getItems()) {
            if (item instanceof Menu sub) {
                collect(sub, path + " → " + plain(sub.getText()), out);
            } else if (item.getAccelerator() != null) {
                out.add(new Key("", item.getAccelerator().getDisplayText(), path + " → " + plain(item.getText())));
            }
        }
    }

    static String plain(String text) {
        return text == null ? "" : text.replace("_", "").replace("…", "");
    }

    static String mnemonic(String text) {
        int i = text == null ? -1 : text.indexOf('_');
        return i < 0 || i + 1 >= text.length() ? "" : text.substring(i + 1, i + 2).toUpperCase(java.util.Locale.ROOT);
    }

    List<Key> all() {
        List<Key> out = new ArrayList<>(menuKeys);
        out.addAll(VIEW_KEYS);
        return out;
    }

    List<Key> forView(String viewId) {
        return VIEW_KEYS.stream().filter(k -> k.viewId().equals(viewId)).toList();
    }

    /** The shortcut sheet: the window's keys, then each view's under its title. */
    String sheet(ViewRegistry registry) {
        StringBuilder s = new StringBuilder("The window\n");
        all().stream().filter(k -> k.viewId().isEmpty()).forEach(k -> s.append(k.line()).append('\n'));
        for (ViewSpec spec : registry.all()) {
            List<Key> keys = forView(spec.id());
            if (!keys.isEmpty()) {
                s.append('\n').append(spec.title()).append('\n');
                keys.forEach(k -> s.append(k.line()).append('\n'));
            }
        }
        return s.toString();
    }
}
