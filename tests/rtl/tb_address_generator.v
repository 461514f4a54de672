// Starts a sweep over +objects=N boxes and writes, for every cycle with
// addresses, "row first valid_mask" in hex.
module tb_address_generator;
    parameter M = 2;
    parameter AW = 16;
    reg clk = 0, start = 0;
    reg [AW:0] objects;
    wire sweeping;
    wire [AW-1:0] row;
    wire [(2*M-1)*AW-1:0] columns;
    wire [2*M-2:0] valid;
    integer n, out;
    address_generator #(.M(M), .AW(AW)) dut (
        .clk(clk), .start(start), .enable(1'b1), .objects(objects),
        .sweeping(sweeping), .row(row), .columns(columns), .valid(valid));
    initial begin
        if (!$value$plusargs("objects=%d", n)) $fatal(1, "+objects=N missing");
        objects = n;
        out = $fopen("results.txt", "w");
        start = 1;
        #1 clk = 1;
        #1 clk = 0;
        start = 0;
        while (sweeping) begin
            $fwrite(out, "%0h %0h %0h\n", row, columns[AW-1:0], valid);
            #1 clk = 1;
            #1 clk = 0;
        end
        $fclose(out);
        $finish;
    end
endmodule
