// The ncvm extension: Fanuc programs get the TextMate grammar (syntaxes/) and the language
// server `ncvm lsp` (diagnostics, hover, go to definition, symbols, completion). The
// settings ncvm.path, ncvm.libs and ncvm.setup say which binary to start and with what.
import * as path from 'path';
import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions } from 'vscode-languageclient/node';

let client: LanguageClient | undefined;

// A relative folder or file in the settings is taken from the first workspace folder.
function resolve(p: string): string {
  const root = vscode.workspace.workspaceFolders?.[0]?.uri.fsPath;
  return path.isAbsolute(p) || !root ? p : path.join(root, p);
}

export function serverArguments(libs: string[], setups: string[]): string[] {
  const args = ['lsp'];
  for (const lib of libs) args.push('--lib', resolve(lib));
  for (const setup of setups) args.push('--setup', resolve(setup));
  return args;
}

async function start(): Promise<void> {
  const config = vscode.workspace.getConfiguration('ncvm');
  const command = config.get<string>('path', 'ncvm');
  const args = serverArguments(config.get<string[]>('libs', []), config.get<string[]>('setup', []));
  const server: ServerOptions = { command, args };
  const options: LanguageClientOptions = {
    documentSelector: [{ language: 'fanuc' }],
  };
  client = new LanguageClient('ncvm', 'ncvm language server', server, options);
  try {
    await client.start();
  } catch (e) {
    void vscode.window.showErrorMessage(
      `ncvm: cannot start "${command} ${args.join(' ')}" (setting ncvm.path): ${String(e)}`,
    );
  }
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  await start();
  // A changed setting restarts the server with the new binary, folders or setup.
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (e) => {
      if (!e.affectsConfiguration('ncvm')) return;
      await client?.stop();
      await start();
    }),
  );
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
