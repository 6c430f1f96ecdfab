package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.record.RecordingException;
import touchline.record.Recovery;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code touchline recover FILE}: writes a finished copy of a recording that did not finish
 * (a killed recorder, a power cut), which the standard MCAP readers open. The damaged file is
 * left as it was; what could not be saved is said.
 */
@Command(name = "recover", mixinStandardHelpOptions = true,
        description = "Write a finished copy of a recording that was cut short (killed recorder, power cut).")
public final class RecoverCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "FILE", description = "the unfinished recording (.mcap)")
    Path file;

    @Option(names = "--out", description = "the finished copy (default: FILE-recovered.mcap beside it)")
    Path out;

    @CommandLine.Mixin
    ExpansionOption expansion = new ExpansionOption();

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter stdout = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Path target = out != null ? out : file.resolveSibling(stem(file) + "-recovered.mcap");
        if (target.toAbsolutePath().normalize().equals(file.toAbsolutePath().normalize())) {
            err.println("touchline recover: --out must differ from FILE (the damaged file is kept as it is)");
            return 2;
        }
        touchline.record.ExpansionLimit limit = expansion.limit(err, "recover");
        if (limit == null) {
            return 2;
        }
        Recovery.Result result;
        try {
            result = new Recovery(file, limit).writeTo(target);
        } catch (RecordingException e) {
            err.println("touchline recover: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            err.println("touchline recover: cannot write " + target + ": " + e.getMessage());
            return 1;
        }
        result.problems().forEach(p -> err.println("note: " + p));
        stdout.printf("recovered %d messages on %d channels to %s%n", result.messages(), result.channels(),
                result.file());
        stdout.flush();
        return 0;
    }

    private static String stem(Path p) {
        String name = p.getFileName().toString();
        return name.endsWith(".mcap") ? name.substring(0, name.length() - 5) : name;
    }
}
